// `hemirad experiment merge DIR`: the sweep's table from its tasks' reports (DIR/results.csv and
// results.md), one row per configuration in index order. Only a task's report.json counts, and it
// appears only when the task's solve is complete, so no partial result enters the table; a
// configuration without one is listed as missing (not run, running or interrupted) or failed
// (with the error lines of DIR/tasks/<id>/error).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "src/output/Figure.h"
#include "src/sweep/SweepSpec.h"

namespace hemirad {

struct SweepTable {
  std::string csv, markdown;
  std::vector<std::string> problems;  // one line per missing or failed configuration
  std::vector<PlotSeries> plot;       // with the spec's plot: y against x, a series per other values
  std::string backend, renderer;      // the first done task's (its report's provenance)
};

SweepTable mergeSweep(const std::string& dir, const Sweep& sweep);
// Writes DIR/results.csv and DIR/results.md (and results.svg and .pdf with a plot), prints the markdown and the
// problems; returns 0 when every configuration is done, else 1.
int runMerge(const std::string& dir);

// A report field by '.'-separated path ("shots", "timings_ms.gather", "objects.floor.mean_radiosity"):
// an array of named objects is indexed by name. Text as in the report (numbers exactly as dumped,
// arrays space-separated); std::nullopt when absent.
std::optional<std::string> reportField(const nlohmann::json& report, const std::string& path);

}  // namespace hemirad
