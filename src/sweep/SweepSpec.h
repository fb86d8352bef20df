// A parameter sweep (docs/sweeps.md): a JSON spec names scenes and axes of `hemirad solve` flags;
// their cross product is the set of configurations, each one solve. The spec is resolved once
// into DIR/sweep.json (every configuration's id, values and full solve command line), which the
// tasks (local or Slurm array tasks) and the merge read, so all three agree on what index N is.
#pragma once
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace hemirad {

struct SweepResources {
  int cpus = 1;
  std::string mem = "2G";         // Slurm's --mem syntax
  std::string time = "01:00:00";  // Slurm's --time syntax
  bool gpu = false;               // --gres=gpu:1 and --backend egl
};

struct SweepConfiguration {
  std::string id;                   // "0003": the task folder's name
  std::vector<std::string> values;  // the scene as written, then each axis's value
  std::vector<std::string> args;    // "solve", the scene (absolute), flags
};

struct Sweep {
  std::string name;
  std::vector<std::string> columns;  // "scene", then each axis's flag name
  std::vector<std::string> metrics;  // report fields, '.'-separated paths
  SweepResources resources;
  unsigned checkpointEvery = 64;  // shots between a task's checkpoints
  std::string plotX, plotY;       // optional figure: a numeric axis against a metric (log-log)
  std::vector<SweepConfiguration> configurations;
};

// Checks one configuration's command line as `hemirad` would parse it; throws InputError.
using ArgsCheck = std::function<void(const std::vector<std::string>& args)>;

// Reads and resolves SPEC: every bad field, and every configuration `check` refuses, is one
// InputError naming it, before anything is written.
Sweep readSweepSpec(const std::string& specPath, const ArgsCheck& check);
nlohmann::json sweepJson(const Sweep& sweep);
// DIR/sweep.json back; InputError when DIR holds no sweep.
Sweep readSweepDir(const std::string& dir);
// Creates DIR/tasks and DIR/logs and writes DIR/sweep.json; refuses a DIR that holds another sweep.
void writeSweepDir(const std::string& dir, const Sweep& sweep);

std::string taskDir(const std::string& dir, const SweepConfiguration& c);  // DIR/tasks/<id>

}  // namespace hemirad
