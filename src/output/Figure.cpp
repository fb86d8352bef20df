#include "src/output/Figure.h"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>

#include "src/base/AtomicFile.h"
#include "src/base/DataDir.h"
#include "src/base/Error.h"

extern char** environ;

namespace hemirad {

namespace fs = std::filesystem;

namespace {

std::string python() {
  const char* env = std::getenv("HEMIRAD_PYTHON");
  return env && *env ? env : HEMIRAD_PYTHON;
}

std::string script() { return dataDir() + "/python/plot.py"; }

// Runs PYTHON plot.py ARG; returns "" on success, else the last line the script printed on stderr.
std::string runScript(const std::string& arg) {
  const std::string log = (fs::temp_directory_path() / ("hemirad_plot_" + std::to_string(getpid()) + ".log")).string();
  posix_spawn_file_actions_t files;
  posix_spawn_file_actions_init(&files);
  posix_spawn_file_actions_addopen(&files, 2, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  std::string py = python(), sc = script(), a = arg;
  char* argv[] = {py.data(), sc.data(), a.data(), nullptr};
  pid_t pid = 0;
  int status = 0;
  const int error = posix_spawn(&pid, py.c_str(), &files, nullptr, argv, environ);
  posix_spawn_file_actions_destroy(&files);
  if (error) return fmt::format("cannot run {}: {}", py, std::strerror(error));
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  std::ifstream in(log);
  std::string line, last;
  while (std::getline(in, line))
    if (!line.empty()) last = line;
  std::error_code ec;
  fs::remove(log, ec);
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return "";
  return last.empty() ? fmt::format("{} {} failed (status {})", py, sc, status) : last;
}

std::string tempName(const std::string& path) {
  const fs::path p(path);
  return (p.parent_path() / (p.stem().string() + ".tmp" + std::to_string(getpid()) + p.extension().string())).string();
}

}  // namespace

FigureSize parseFigureSize(const std::string& text) {
  if (text.empty()) return {};
  if (text == "column") return {3.5, 2.6};
  if (text == "page") return {7.0, 4.2};
  double w = 0, h = 0;
  char comma = 0, extra = 0;
  if (std::sscanf(text.c_str(), "%lf %c %lf %c", &w, &comma, &h, &extra) == 3 && comma == ',' && w >= 1 && h >= 1 &&
      w <= 40 && h <= 40)
    return {w, h};
  fail("--figure-size {}: give column, page or W,H in inches (each 1 to 40)", text);
}

void checkPlotting() {
  static bool checked = false;
  if (checked) return;
  if (!fs::exists(script())) fail("figures need the plot script {}, which is missing", script());
  if (std::string problem = runScript("--check"); !problem.empty())
    fail("figures need python3 with matplotlib (Debian package python3-matplotlib): {}", problem);
  checked = true;
}

void Figures::add(const std::string& stem, const LinePlot& plot) {
  nlohmann::json series = nlohmann::json::array();
  for (const PlotSeries& s : plot.series) series.push_back({{"label", s.label}, {"x", s.x}, {"y", s.y}});
  stems_.push_back(stem);
  specs_.push_back(nlohmann::json{{"kind", "lines"},
                                  {"title", plot.title},
                                  {"x_label", plot.xLabel},
                                  {"y_label", plot.yLabel},
                                  {"log_x", plot.logX},
                                  {"log_y", plot.logY},
                                  {"series", series}});
}

void Figures::add(const std::string& stem, const HeatMap& map) {
  nlohmann::json rows = nlohmann::json::array();
  for (int y = 0; y < map.height; ++y) {
    nlohmann::json row = nlohmann::json::array();
    for (int x = 0; x < map.width; ++x) {
      const double v = map.values[std::size_t(y) * std::size_t(map.width) + std::size_t(x)];
      row.push_back(std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr));
    }
    rows.push_back(std::move(row));
  }
  nlohmann::json spec{{"kind", "heatmap"}, {"title", map.title}, {"values", rows},  {"colour_label", map.colourLabel},
                      {"log", map.log},    {"vmin", map.vmin},   {"vmax", map.vmax}};
  if (!map.classes.empty()) {
    spec["classes"] = nlohmann::json::array();
    for (const auto& [label, colour] : map.classes) spec["classes"].push_back({{"label", label}, {"colour", colour}});
  }
  stems_.push_back(stem);
  specs_.push_back(std::move(spec));
}

void Figures::write() {
  if (stems_.empty()) return;
  checkPlotting();
  const std::string provenance = provenanceText(provenance_);
  nlohmann::json batch = nlohmann::json::array();
  std::vector<std::pair<std::string, std::string>> renames;  // temporary name, final name
  for (std::size_t i = 0; i < stems_.size(); ++i) {
    nlohmann::json& spec = specs_[i];
    spec["provenance"] = provenance;
    if (size_.width > 0)
      spec["size"] = {size_.width, size_.height};
    else
      spec["size"] = spec["kind"] == "heatmap" ? nlohmann::json{6.4, 5.4} : nlohmann::json{6.4, 4.2};
    for (const char* ext : {"svg", "pdf"}) {
      const std::string path = stems_[i] + "." + ext;
      renames.emplace_back(tempName(path), path);
      spec[ext] = renames.back().first;
    }
    batch.push_back(spec);
  }
  const std::string specPath = tempName(stems_.front() + "_figures.json");
  std::error_code ec;
  auto cleanUp = [&] {
    fs::remove(specPath, ec);
    for (const auto& r : renames) fs::remove(r.first, ec);
  };
  writeTextFile(specPath, batch.dump());
  if (std::string problem = runScript(specPath); !problem.empty()) {
    cleanUp();
    throw std::runtime_error(fmt::format("drawing {}.svg: {}", stems_.front(), problem));
  }
  for (const auto& [tmp, path] : renames) fs::rename(tmp, path);
  fs::remove(specPath, ec);
  stems_.clear(), specs_.clear();
}

}  // namespace hemirad
