// Figures for papers, drawn by matplotlib: hemirad computes the data, writes it as JSON and runs
// the shipped script (python/plot.py, installed as share/hemirad/python/plot.py; found beside the
// binary, base/DataDir.h) once per batch. Each figure is written as STEM.svg and STEM.pdf with real
// ticks, colour bars on heat maps and the run's provenance (Provenance.h) in their metadata. Same
// data, same bytes (fixed SVG hash salt, no dates).
#pragma once
#include <string>
#include <utility>
#include <vector>

#include "src/output/Provenance.h"

namespace hemirad {

struct PlotSeries {
  std::string label;
  std::vector<double> x, y;
};

// Points with x <= 0 (log x) or y <= 0 (log y) are left out.
struct LinePlot {
  std::string title, xLabel, yLabel;
  bool logX = false, logY = false;
  std::vector<PlotSeries> series;
};

// A width x height grid of values, row 0 at the bottom (atlas texels); NaN: no data (black).
struct HeatMap {
  std::string title, colourLabel;
  int width = 0, height = 0;
  std::vector<double> values;
  bool log = false;  // log colour scale over [vmin, vmax]
  double vmin = 0, vmax = 1;
  // Or categories: values are indices into {label, "#rrggbb"}, shown on the colour bar by name.
  std::vector<std::pair<std::string, std::string>> classes;
};

// Fails now (InputError, one line) if the plot script, python3 or matplotlib is missing: called
// before long work by every command that draws figures. HEMIRAD_PYTHON picks the interpreter
// (default: the system's python3, where Debian's python3-matplotlib lives).
void checkPlotting();

// A figure's size in inches (`--figure-size`): `column` (3.5 x 2.6, one column of a two-column
// paper), `page` (7 x 4.2, the full text width) or `W,H`. Unset: 6.4 x 4.2 (plots), 6.4 x 5.4 (maps).
struct FigureSize {
  double width = 0, height = 0;  // 0: each kind's default
};
// InputError (naming --figure-size) for anything else; "" is the default.
FigureSize parseFigureSize(const std::string& text);

// A batch of figures drawn by one run of the script (matplotlib's import is most of its cost).
// Figures carry no title inside (a paper's caption says it): the title is in the file's metadata.
class Figures {
 public:
  explicit Figures(Provenance provenance, FigureSize size = {}) : provenance_(std::move(provenance)), size_(size) {}
  void add(const std::string& stem, const LinePlot& plot);
  void add(const std::string& stem, const HeatMap& map);
  // Draws them all; every STEM.svg and STEM.pdf appears whole or not at all.
  void write();

 private:
  Provenance provenance_;
  FigureSize size_;
  std::vector<std::string> stems_;
  std::vector<nlohmann::json> specs_;  // each figure, without its output paths
};

}  // namespace hemirad
