// `hemirad experiment SPEC --slurm DIR | --out-dir DIR [--jobs N]`, `experiment merge DIR` and
// `experiment run-task DIR INDEX` (docs/sweeps.md): the sweep library driven by the CLI, whose
// parser checks each configuration's solve flags and runs each task's solve in-process.
#pragma once
#include <string>
#include <vector>

namespace hemirad {

struct SweepCommandOptions {
  std::string spec;        // SPEC.json; empty: the seed-004 experiment
  std::string slurm;       // --slurm DIR
  std::string outDir;      // --out-dir DIR, for a local run
  unsigned jobs = 1;       // --jobs
  std::string dir, index;  // merge DIR, run-task DIR INDEX
};

// Writes the Slurm sweep, or runs it locally and merges; returns the exit code.
int runSweepCommand(const SweepCommandOptions& o);
int runSweepTaskCommand(const SweepCommandOptions& o);
int runSweepMergeCommand(const SweepCommandOptions& o);

// `hemirad ARGS` parsed as the CLI would (InputError for what it refuses) and checked as far as
// is possible without running: the configurations of a spec.
void checkHemiradArgs(const std::vector<std::string>& args);

}  // namespace hemirad
