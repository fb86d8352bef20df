#include "src/sweep/SweepMerge.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "src/base/AtomicFile.h"
#include "src/base/Error.h"
#include "src/output/Figure.h"

namespace hemirad {

namespace fs = std::filesystem;

namespace {

std::string text(const nlohmann::json& v) {
  if (v.is_string()) return v.get<std::string>();
  if (!v.is_array()) return v.dump();
  std::string out;
  for (const auto& e : v) out += (out.empty() ? "" : " ") + text(e);
  return out;
}

std::string csvCell(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::string readText(const std::string& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

struct Row {
  std::vector<std::string> cells;  // id, values, metrics, status
  std::string problem;             // "" when done
  std::string backend, renderer;   // the report's
};

Row mergeRow(const std::string& dir, const Sweep& sweep, const SweepConfiguration& c) {
  const std::string task = taskDir(dir, c);
  Row row{{c.id}, {}, {}, {}};
  row.cells.insert(row.cells.end(), c.values.begin(), c.values.end());
  std::string status = "done";
  if (fs::exists(task + "/report.json")) {
    nlohmann::json report;
    try {
      report = nlohmann::json::parse(readText(task + "/report.json"));
    } catch (const nlohmann::json::exception& e) {
      fail("{}/report.json: damaged: {}", task, e.what());
    }
    if (report.value("scene", "") != c.args.at(1))
      fail("{}/report.json is of scene {}, not this sweep's {}", task, report.value("scene", "?"), c.args.at(1));
    for (const std::string& m : sweep.metrics) row.cells.push_back(reportField(report, m).value_or(""));
    row.backend = report.value("backend", ""), row.renderer = report.value("renderer", "");
  } else {
    std::string error = readText(task + "/error");
    while (!error.empty() && error.back() == '\n') error.pop_back();
    status = !error.empty() ? "failed" : fs::exists(task + "/checkpoint.ckpt") ? "missing (checkpointed)" : "missing";
    row.cells.resize(row.cells.size() + sweep.metrics.size());
    row.problem = fmt::format("configuration {} ({}): {}{}", c.id, fmt::join(c.values, ", "), status,
                              error.empty() ? "" : ": " + error);
  }
  row.cells.push_back(status);
  return row;
}

// A done row's point on the spec's plot, in the series of its other values.
void addPoint(const Sweep& sweep, const std::vector<std::string>& cells, std::vector<PlotSeries>& plot) {
  const std::size_t xColumn =
      std::find(sweep.columns.begin(), sweep.columns.end(), sweep.plotX) - sweep.columns.begin();
  const std::size_t yCell =
      1 + sweep.columns.size() +
      (std::find(sweep.metrics.begin(), sweep.metrics.end(), sweep.plotY) - sweep.metrics.begin());
  std::string label;
  for (std::size_t k = 0; k < sweep.columns.size(); ++k)
    if (k != xColumn)
      label += fmt::format("{}{}={}", label.empty() ? "" : ", ", sweep.columns[k],
                           k == 0 ? fs::path(cells[1]).stem().string() : cells[1 + k]);
  auto series = std::find_if(plot.begin(), plot.end(), [&](const PlotSeries& s) { return s.label == label; });
  if (series == plot.end()) series = plot.insert(plot.end(), PlotSeries{label, {}, {}});
  series->x.push_back(std::strtod(cells[1 + xColumn].c_str(), nullptr));
  series->y.push_back(std::strtod(cells[yCell].c_str(), nullptr));
}

// The figure's provenance: this hemirad, the tasks' backend, and the sweep rather than the command
// that merged it, so a merge after Slurm tasks and a local run give the same bytes.
Provenance sweepProvenance(const Sweep& sweep, const SweepTable& t) {
  Provenance p = provenance(t.backend, t.renderer);
  p.commandLine = fmt::format("sweep {} ({} configurations, varying {}); the first: hemirad {}", sweep.name,
                              sweep.configurations.size(), fmt::join(sweep.columns, ", "),
                              fmt::join(sweep.configurations.front().args, " "));
  return p;
}

}  // namespace

std::optional<std::string> reportField(const nlohmann::json& report, const std::string& path) {
  const nlohmann::json* v = &report;
  std::stringstream parts(path);
  for (std::string part; std::getline(parts, part, '.');) {
    const nlohmann::json* next = nullptr;
    if (v->is_object() && v->contains(part)) next = &(*v)[part];
    if (v->is_array())
      for (const auto& e : *v)
        if (e.is_object() && e.value("name", "") == part) next = &e;
    if (!next) return std::nullopt;
    v = next;
  }
  return text(*v);
}

SweepTable mergeSweep(const std::string& dir, const Sweep& sweep) {
  std::vector<std::string> header = {"id"};
  header.insert(header.end(), sweep.columns.begin(), sweep.columns.end());
  header.insert(header.end(), sweep.metrics.begin(), sweep.metrics.end());
  header.push_back("status");
  SweepTable t;
  auto addLine = [&t](const std::vector<std::string>& cells) {
    std::string csv, md = "|";
    for (std::size_t k = 0; k < cells.size(); ++k)
      csv += (k ? "," : "") + csvCell(cells[k]), md += " " + cells[k] + " |";
    t.csv += csv + "\n", t.markdown += md + "\n";
  };
  t.markdown = fmt::format("# Sweep {}: {} configurations\n\n", sweep.name, sweep.configurations.size());
  addLine(header);
  t.markdown += "|";
  for (std::size_t k = 0; k < header.size(); ++k) t.markdown += "---|";
  t.markdown += "\n";
  for (const SweepConfiguration& c : sweep.configurations) {
    Row row = mergeRow(dir, sweep, c);
    addLine(row.cells);
    if (!row.problem.empty())
      t.problems.push_back(row.problem);
    else if (!sweep.plotX.empty())
      addPoint(sweep, row.cells, t.plot);
    if (row.problem.empty() && t.backend.empty()) t.backend = row.backend, t.renderer = row.renderer;
  }
  if (!t.problems.empty()) {
    t.markdown +=
        fmt::format("\n{} of {} configurations not done:\n\n", t.problems.size(), sweep.configurations.size());
    for (const std::string& p : t.problems) t.markdown += "- " + p + "\n";
  }
  return t;
}

int runMerge(const std::string& dir) {
  const Sweep sweep = readSweepDir(dir);
  if (!sweep.plotX.empty()) checkPlotting();
  const SweepTable t = mergeSweep(dir, sweep);
  writeTextFile(dir + "/results.csv", t.csv);
  writeTextFile(dir + "/results.md", t.markdown);
  if (!sweep.plotX.empty()) {  // points with x or y <= 0 (or not numbers) are left out: log axes
    Figures figures(sweepProvenance(sweep, t));
    figures.add(dir + "/results", LinePlot{fmt::format("sweep {}: {} against {}", sweep.name, sweep.plotY, sweep.plotX),
                                           sweep.plotX, sweep.plotY, true, true, t.plot});
    figures.write();
  }
  fmt::print("{}", t.markdown);
  for (const std::string& p : t.problems) fmt::print(stderr, "hemirad sweep {}: {}\n", sweep.name, p);
  fmt::print(stderr, "hemirad sweep {}: {} of {} configurations done; table in {}/results.csv and results.md\n",
             sweep.name, sweep.configurations.size() - t.problems.size(), sweep.configurations.size(), dir);
  return t.problems.empty() ? 0 : kExitFailure;
}

}  // namespace hemirad
