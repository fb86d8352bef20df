#include "src/sweep/SweepTask.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <algorithm>
#include <cstring>
#include <filesystem>
#include <map>

#include "src/base/AtomicFile.h"
#include "src/base/Error.h"
#include "src/solver/Checkpoint.h"

extern char** environ;

namespace hemirad {

namespace fs = std::filesystem;

namespace {

const SweepConfiguration& configuration(const Sweep& sweep, const std::string& dir, const std::string& index) {
  char* end = nullptr;
  const unsigned long i = std::strtoul(index.c_str(), &end, 10);
  if (index.empty() || *end != '\0' || index[0] == '-' || i >= sweep.configurations.size())
    fail("run-task {} {}: the index must be 0 to {}", dir, index, sweep.configurations.size() - 1);
  return sweep.configurations[i];
}

// Perspective-driven shooting has no checkpoint (docs/checkpoints.md): such a task restarts.
bool resumable(const std::vector<std::string>& args) {
  auto a = std::find(args.begin(), args.end(), "--algorithm");
  return a == args.end() || a + 1 == args.end() || a[1] != "perspective";
}

std::string describe(const Sweep& sweep, const SweepConfiguration& c) {
  std::string out;
  for (std::size_t k = 0; k < c.values.size(); ++k)
    out += fmt::format("{}{}={}", k ? " " : "", sweep.columns[k], c.values[k]);
  return out;
}

// The solve's command line: the configuration's, writing the task's report and checkpoint, and
// resuming from the checkpoint when one is there.
std::vector<std::string> taskArgs(const Sweep& sweep, const SweepConfiguration& c, const std::string& tag,
                                  const std::string& task) {
  const std::string ck = task + "/checkpoint.ckpt";
  std::vector<std::string> args = c.args;
  args.insert(args.end(), {"--report", task + "/report.json", "--quiet"});
  if (resumable(args)) {
    args.insert(args.end(), {"--checkpoint", ck, "--checkpoint-every", std::to_string(sweep.checkpointEvery)});
    if (fs::exists(ck)) {
      fmt::print(stderr, "{}: resuming from its checkpoint at {} shots\n", tag, readCheckpoint(ck).shots);
      args.insert(args.end(), {"--resume", ck});
    }
  }
  fmt::print(stderr, "{}: hemirad {}\n", tag, fmt::join(args, " "));
  return args;
}

}  // namespace

int runSweepTask(const std::string& dir, const std::string& index, const SolveRunner& solve) {
  const Sweep sweep = readSweepDir(dir);
  const SweepConfiguration& c = configuration(sweep, dir, index);
  const std::string task = taskDir(dir, c), report = task + "/report.json", ck = task + "/checkpoint.ckpt";
  fs::create_directories(task);
  const std::string tag = fmt::format("hemirad sweep: task {} ({})", c.id, describe(sweep, c));
  if (fs::exists(report)) {
    fmt::print(stderr, "{}: already done\n", tag);
    return 0;
  }
  fs::remove(task + "/error");  // a failed task run again
  int code = 0;
  try {
    code = solve(taskArgs(sweep, c, tag, task));
  } catch (const std::exception& e) {  // a bad checkpoint too: the task fails with its line
    writeTextFile(task + "/error", fmt::format("hemirad: error: {}\n", e.what()));
    throw;
  }
  if (code == 0 && fs::exists(report)) {
    fmt::print(stderr, "{}: done\n", tag);
  } else if (code > 128) {
    fmt::print(stderr, "{}: stopped by a signal; {}\n", tag,
               fs::exists(ck) ? fmt::format("its checkpoint ({} shots) resumes it", readCheckpoint(ck).shots)
                              : std::string("no checkpoint yet, it restarts"));
  } else {
    writeTextFile(task + "/error", fmt::format("hemirad: error: hemirad solve exited with {}, no report\n", code));
    if (code == 0) code = kExitFailure;
  }
  return code;
}

std::string selfExecutable() { return fs::read_symlink("/proc/self/exe").string(); }

namespace {

pid_t spawnTask(const std::string& exe, const std::string& dir, std::size_t index) {
  const std::string log = fmt::format("{}/logs/task_{}.log", dir, index), i = std::to_string(index);
  posix_spawn_file_actions_t files;
  posix_spawn_file_actions_init(&files);
  posix_spawn_file_actions_addopen(&files, 1, log.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
  posix_spawn_file_actions_adddup2(&files, 1, 2);
  std::vector<std::string> args = {exe, "experiment", "run-task", dir, i};
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int error = posix_spawn(&pid, exe.c_str(), &files, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&files);
  if (error) throw std::runtime_error(fmt::format("cannot start {}: {}", exe, std::strerror(error)));
  return pid;
}

}  // namespace

unsigned runSweepLocally(const std::string& dir, const Sweep& sweep, unsigned jobs) {
  const std::string exe = selfExecutable();
  std::map<pid_t, std::size_t> running;
  std::size_t next = 0;
  unsigned failed = 0, finished = 0;
  while (next < sweep.configurations.size() || !running.empty()) {
    while (running.size() < jobs && next < sweep.configurations.size()) {
      running[spawnTask(exe, dir, next)] = next;
      ++next;
    }
    int status = 0;
    const pid_t pid = waitpid(-1, &status, 0);
    if (pid < 0) throw std::runtime_error(fmt::format("waiting for the sweep's tasks: {}", std::strerror(errno)));
    auto it = running.find(pid);
    if (it == running.end()) continue;
    const bool ok = WIFEXITED(status) && WEXITSTATUS(status) == 0;
    if (!ok) ++failed;
    fmt::print(stderr, "hemirad sweep: task {} {}, {} of {} finished (log: {}/logs/task_{}.log)\n",
               sweep.configurations[it->second].id, ok ? "done" : "failed", ++finished, sweep.configurations.size(),
               dir, it->second);
    running.erase(it);
  }
  return failed;
}

}  // namespace hemirad
