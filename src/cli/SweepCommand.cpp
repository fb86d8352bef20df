#include "src/cli/SweepCommand.h"

#include <fmt/format.h>

#include <filesystem>
#include <memory>

#include "src/base/AtomicFile.h"
#include "src/base/Error.h"
#include "src/cli/Commands.h"
#include "src/options/Suggest.h"
#include "src/output/Figure.h"
#include "src/sweep/SlurmScript.h"
#include "src/sweep/SweepMerge.h"
#include "src/sweep/SweepTask.h"

namespace hemirad {

namespace fs = std::filesystem;

namespace {

std::unique_ptr<Commands> parsed(const std::vector<std::string>& args) {
  auto commands = std::make_unique<Commands>();
  if (std::string message = options::unknownName(commands->app, args); !message.empty()) throw InputError(message);
  std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 takes them last first
  try {
    commands->app.parse(reversed);
  } catch (const CLI::ParseError& e) {
    throw InputError(e.what());
  }
  return commands;
}

int solveInProcess(const std::vector<std::string>& args) { return parsed(args)->run(); }

std::string absoluteDir(const std::string& dir) { return fs::absolute(dir).lexically_normal().string(); }

Sweep readSpec(const std::string& spec) {
  return readSweepSpec(spec, [](const std::vector<std::string>& args) { checkHemiradArgs(args); });
}

}  // namespace

void checkHemiradArgs(const std::vector<std::string>& args) { parsed(args)->settle(); }

int runSweepCommand(const SweepCommandOptions& o) {
  if (o.slurm.empty() == o.outDir.empty())
    fail("experiment {}: give --slurm DIR (write a Slurm job array) or --out-dir DIR (run here, --jobs N at a time)",
         o.spec);
  const Sweep sweep = readSpec(o.spec);
  if (!o.slurm.empty()) {
    const std::string dir = absoluteDir(o.slurm);
    const std::string script = slurmScript(sweep, selfExecutable(), dir);  // checks the paths first
    writeSweepDir(dir, sweep);
    writeTextFile(dir + "/sweep.sbatch", script);
    fmt::print("{}", script);
    fmt::print(stderr,
               "hemirad sweep {}: {} configurations; submit with: sbatch {}/sweep.sbatch\n"
               "then, when they are done: hemirad experiment merge {}\n",
               sweep.name, sweep.configurations.size(), dir, dir);
    return 0;
  }
  if (!sweep.plotX.empty()) checkPlotting();  // the merge draws results.svg: fail before the solves
  const std::string dir = absoluteDir(o.outDir);
  writeSweepDir(dir, sweep);
  fmt::print(stderr, "hemirad sweep {}: {} configurations, {} at a time, into {}\n", sweep.name,
             sweep.configurations.size(), o.jobs, dir);
  runSweepLocally(dir, sweep, o.jobs);
  return runMerge(dir);
}

int runSweepTaskCommand(const SweepCommandOptions& o) { return runSweepTask(o.dir, o.index, solveInProcess); }

int runSweepMergeCommand(const SweepCommandOptions& o) { return runMerge(o.dir); }

}  // namespace hemirad
