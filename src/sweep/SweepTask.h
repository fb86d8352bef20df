// Running a sweep's configurations: one task (`hemirad experiment run-task DIR INDEX`, what each
// Slurm array task runs) and the local pool (`--jobs N`), which runs the same command as child
// processes, so a local and a Slurm run of one spec fill DIR/tasks/ with the same files.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "src/sweep/SweepSpec.h"

namespace hemirad {

// Runs `hemirad ARGS` in this process (the CLI's parser and commands); returns its exit code.
using SolveRunner = std::function<int(const std::vector<std::string>& args)>;

// Runs configuration INDEX of the sweep in DIR into DIR/tasks/<id>/: its solve checkpoints to
// checkpoint.ckpt and resumes from it when there (a requeued task), and its report.json appears,
// renamed into place, only when the solve is complete. A done task returns at once. On failure
// the error line goes to DIR/tasks/<id>/error too. Returns the solve's exit code (143 when
// stopped by SIGTERM, its checkpoint written).
int runSweepTask(const std::string& dir, const std::string& index, const SolveRunner& solve);

// Runs every configuration of the sweep in DIR, `jobs` child processes at a time, each
// `hemirad experiment run-task DIR INDEX` logging to DIR/logs/task_INDEX.log (as Slurm's
// --output). Returns the number of tasks that failed.
unsigned runSweepLocally(const std::string& dir, const Sweep& sweep, unsigned jobs);

// This binary's absolute path (what the tasks and the Slurm script run).
std::string selfExecutable();

}  // namespace hemirad
