#include "src/sweep/SweepSpec.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>

#include "src/base/AtomicFile.h"
#include "src/base/Error.h"
#include "src/output/Report.h"

namespace hemirad {

namespace fs = std::filesystem;
using ojson = nlohmann::ordered_json;  // axes keep the spec's order: the last varies fastest

namespace {

// Flags each task sets itself (its report, checkpoint, backend) or that write files the tasks
// would share: a spec naming one is refused.
const std::set<std::string> kTaskFlags = {
    "report", "checkpoint", "checkpoint-every", "resume", "quiet", "backend", "gpu", "out", "image",
    "atlas",  "ply",        "camera-path",      "frames"};

ojson readJsonFile(const std::string& path, const std::string& what) {
  std::ifstream in(path);
  if (!in) fail("{} {}: cannot be read", what, path);
  try {
    return ojson::parse(in);
  } catch (const nlohmann::json::exception& e) {
    fail("{} {}: not valid JSON: {}", what, path, e.what());
  }
}

// A spec value as it goes on the command line ("" for a switch's true) and into the table.
std::string valueText(const std::string& spec, const std::string& flag, const ojson& v) {
  if (v.is_string()) return v.get<std::string>();
  if (v.is_number() || v.is_boolean()) return v.dump();
  fail("{}: {}: values must be strings, numbers or true/false, not {}", spec, flag, v.dump());
}

void addFlag(std::vector<std::string>& args, const std::string& flag, const std::string& value) {
  if (value == "false") return;  // a switch left off
  args.push_back("--" + flag);
  if (value != "true") args.push_back(value);
}

void checkFlagName(const std::string& spec, const std::string& flag) {
  if (flag.rfind("--", 0) == 0) fail("{}: flag '{}': name it without the leading --", spec, flag);
  if (kTaskFlags.count(flag))
    fail("{}: --{} is set by each task (or would make the tasks write one file); leave it out of the spec", spec, flag);
}

SweepResources readResources(const std::string& spec, const ojson& r) {
  SweepResources out;
  for (const auto& [key, v] : r.items()) {
    if (key == "cpus" && v.is_number_integer() && v.get<int>() >= 1)
      out.cpus = v.get<int>();
    else if (key == "mem" && v.is_string())
      out.mem = v.get<std::string>();
    else if (key == "time" && v.is_string())
      out.time = v.get<std::string>();
    else if (key == "gpu" && v.is_boolean())
      out.gpu = v.get<bool>();
    else
      fail("{}: resources.{} = {}: expected cpus (integer >= 1), mem (\"4G\"), time (\"02:00:00\") or gpu (true/false)",
           spec, key, v.dump());
  }
  for (const std::string* s : {&out.mem, &out.time})
    if (s->empty() || s->find_first_of(" \t\n'\"$`\\") != std::string::npos)
      fail("{}: resources: '{}' is not a Slurm value", spec, *s);
  return out;
}

// A metric must start with a report field (docs/design.md#report).
void checkMetric(const std::string& spec, const std::string& metric) {
  const nlohmann::json fields = reportJson(RunInfo{});
  const std::string first = metric.substr(0, metric.find('.'));
  if (!fields.contains(first)) {
    std::string names;
    for (const auto& [key, v] : fields.items()) names += (names.empty() ? "" : ", ") + key;
    fail("{}: metric '{}': '{}' is not a report field ({})", spec, metric, first, names);
  }
}

std::vector<std::string> stringList(const std::string& spec, const ojson& j, const char* key) {
  if (!j.contains(key) || !j[key].is_array() || j[key].empty())
    fail("{}: '{}' must be a non-empty list of strings", spec, key);
  std::vector<std::string> out;
  for (const ojson& v : j[key]) {
    if (!v.is_string() || v.get<std::string>().empty()) fail("{}: '{}' must be a non-empty list of strings", spec, key);
    out.push_back(v.get<std::string>());
  }
  return out;
}

// The spec's axes (each flag with its values, in the spec's order; their names appended to
// `columns`) and the flags every configuration gets, as command-line words.
struct SpecFlags {
  std::vector<std::pair<std::string, std::vector<std::string>>> axes;
  std::vector<std::string> fixed;
};

SpecFlags readFlags(const std::string& spec, const ojson& j, std::vector<std::string>& columns) {
  const ojson axes = j.value("axes", ojson::object()), flags = j.value("flags", ojson::object());
  if (!axes.is_object() || !flags.is_object()) fail("{}: 'axes' and 'flags' are objects: {{\"flag\": ...}}", spec);
  SpecFlags out;
  for (const auto& [flag, values] : axes.items()) {
    checkFlagName(spec, flag);
    if (!values.is_array() || values.empty()) fail("{}: axes.{} must be a non-empty list of values", spec, flag);
    out.axes.push_back({flag, {}});
    for (const ojson& v : values) out.axes.back().second.push_back(valueText(spec, flag, v));
    columns.push_back(flag);
  }
  for (const auto& [flag, v] : flags.items()) {
    checkFlagName(spec, flag);
    addFlag(out.fixed, flag, valueText(spec, flag, v));
  }
  return out;
}

// "plot": {"x": AXIS, "y": METRIC}: merge also draws results.svg.
void readPlot(const std::string& spec, const ojson& j, Sweep& s) {
  if (!j.contains("plot")) return;
  const ojson& p = j["plot"];
  if (!p.is_object() || p.size() != 2 || !p.contains("x") || !p.contains("y") || !p["x"].is_string() ||
      !p["y"].is_string())
    fail("{}: plot must be {{\"x\": AXIS, \"y\": METRIC}}", spec);
  s.plotX = p["x"], s.plotY = p["y"];
  if (std::find(s.columns.begin() + 1, s.columns.end(), s.plotX) == s.columns.end())
    fail("{}: plot.x '{}' is not one of the axes", spec, s.plotX);
  if (std::find(s.metrics.begin(), s.metrics.end(), s.plotY) == s.metrics.end())
    fail("{}: plot.y '{}' is not one of the metrics", spec, s.plotY);
}

// Scenes x axes, the last axis varying fastest.
std::vector<SweepConfiguration> crossProduct(const std::string& spec, const std::vector<std::string>& scenes,
                                             const std::vector<std::pair<std::string, std::vector<std::string>>>& axes,
                                             const std::vector<std::string>& fixed) {
  std::vector<std::vector<std::string>> rows;
  for (const std::string& s : scenes) rows.push_back({s});
  for (const auto& axis : axes) {
    std::vector<std::vector<std::string>> next;
    for (const auto& row : rows)
      for (const std::string& v : axis.second) {
        next.push_back(row);
        next.back().push_back(v);
      }
    rows = std::move(next);
  }
  if (rows.size() > 100000) fail("{}: {} configurations; at most 100,000", spec, rows.size());
  std::vector<SweepConfiguration> out;
  for (const auto& row : rows) {
    const std::string scene = fs::absolute(row[0]).lexically_normal().string();
    SweepConfiguration c{fmt::format("{:04}", out.size()), row, {"solve", scene}};
    for (std::size_t a = 0; a < axes.size(); ++a) addFlag(c.args, axes[a].first, row[a + 1]);
    c.args.insert(c.args.end(), fixed.begin(), fixed.end());
    out.push_back(std::move(c));
  }
  return out;
}

}  // namespace

Sweep readSweepSpec(const std::string& spec, const ArgsCheck& check) {
  const ojson j = readJsonFile(spec, "sweep spec");
  if (!j.is_object()) fail("{}: a sweep spec is a JSON object (docs/sweeps.md)", spec);
  const std::set<std::string> known = {"name",      "scenes",           "axes",    "flags",
                                       "resources", "checkpoint_every", "metrics", "plot"};
  for (const auto& [key, v] : j.items())
    if (!known.count(key)) fail("{}: unknown field '{}' (known: {})", spec, key, fmt::join(known, ", "));
  Sweep s;
  s.name = j.contains("name") && j["name"].is_string() ? j["name"].get<std::string>() : fs::path(spec).stem().string();
  const char* kNameChars = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_.-";
  if ((j.contains("name") && !j["name"].is_string()) || s.name.empty() ||
      s.name.find_first_not_of(kNameChars) != std::string::npos)
    fail("{}: name {}: letters, digits, '_', '.' and '-' only (it names the Slurm job)", spec,
         j.contains("name") ? j["name"].dump() : s.name);
  const std::vector<std::string> scenes = stringList(spec, j, "scenes");
  s.metrics = stringList(spec, j, "metrics");
  for (const std::string& m : s.metrics) checkMetric(spec, m);
  s.columns = {"scene"};
  SpecFlags flags = readFlags(spec, j, s.columns);
  const ojson resources = j.value("resources", ojson::object());
  if (!resources.is_object()) fail("{}: 'resources' is an object: {{\"cpus\": 2, ...}}", spec);
  s.resources = readResources(spec, resources);
  if (s.resources.gpu) flags.fixed.insert(flags.fixed.end(), {"--backend", "egl"});  // the GPU Slurm gives it
  if (j.contains("checkpoint_every")) {
    if (!j["checkpoint_every"].is_number_unsigned() || j["checkpoint_every"].get<unsigned>() == 0)
      fail("{}: checkpoint_every must be a positive integer (shots)", spec);
    s.checkpointEvery = j["checkpoint_every"].get<unsigned>();
  }
  readPlot(spec, j, s);
  s.configurations = crossProduct(spec, scenes, flags.axes, flags.fixed);
  for (const SweepConfiguration& c : s.configurations) {
    try {
      check(c.args);
    } catch (const InputError& e) {
      fail("{}: configuration {} ({}): {}", spec, c.id, fmt::join(c.values, ", "), e.what());
    }
  }
  return s;
}

nlohmann::json sweepJson(const Sweep& s) {
  nlohmann::json configs = nlohmann::json::array();
  for (const SweepConfiguration& c : s.configurations)
    configs.push_back({{"id", c.id}, {"values", c.values}, {"args", c.args}});
  return {
      {"name", s.name},
      {"columns", s.columns},
      {"metrics", s.metrics},
      {"resources",
       {{"cpus", s.resources.cpus}, {"mem", s.resources.mem}, {"time", s.resources.time}, {"gpu", s.resources.gpu}}},
      {"checkpoint_every", s.checkpointEvery},
      {"plot", {{"x", s.plotX}, {"y", s.plotY}}},
      {"configurations", configs}};
}

Sweep readSweepDir(const std::string& dir) {
  const std::string path = dir + "/sweep.json";
  if (!fs::exists(path))
    fail("{}: no sweep here (no sweep.json; make one with hemirad experiment SPEC --slurm DIR)", dir);
  try {
    const nlohmann::json j = nlohmann::json::parse(std::ifstream(path));
    Sweep s;
    s.name = j.at("name");
    s.columns = j.at("columns").get<std::vector<std::string>>();
    s.metrics = j.at("metrics").get<std::vector<std::string>>();
    const auto& r = j.at("resources");
    s.resources = {r.at("cpus"), r.at("mem"), r.at("time"), r.at("gpu")};
    s.checkpointEvery = j.at("checkpoint_every");
    s.plotX = j.at("plot").at("x"), s.plotY = j.at("plot").at("y");
    for (const auto& c : j.at("configurations")) s.configurations.push_back({c.at("id"), c.at("values"), c.at("args")});
    return s;
  } catch (const nlohmann::json::exception& e) {
    fail("{}: damaged: {}", path, e.what());
  }
}

void writeSweepDir(const std::string& dir, const Sweep& sweep) {
  const std::string text = sweepJson(sweep).dump(1) + "\n";
  const std::string path = dir + "/sweep.json";
  if (fs::exists(path)) {
    std::ifstream in(path);
    const std::string old((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (old != text)
      fail("{} holds another sweep (its sweep.json differs): merge or remove it, or choose another folder", dir);
  }
  std::error_code ec;
  fs::create_directories(dir + "/tasks", ec);
  fs::create_directories(dir + "/logs", ec);
  checkWritable(path, "sweep folder");
  writeTextFile(path, text);
}

std::string taskDir(const std::string& dir, const SweepConfiguration& c) { return dir + "/tasks/" + c.id; }

}  // namespace hemirad
