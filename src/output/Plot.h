// Line plots as PNG for the validation figures, drawn with OpenImageIO (lines, boxes, text in
// DejaVu Sans). Readable axes, ticks, labels and a legend; no plotting dependency.
#pragma once
#include <string>
#include <vector>

namespace hemirad {

struct PlotSeries {
  std::string label;
  std::vector<double> x, y;
};

struct PlotSpec {
  std::string title, xLabel, yLabel;
  bool logY = false;
  int width = 960, height = 640;
};

void writeLinePlot(const std::string& path, const PlotSpec& spec, const std::vector<PlotSeries>& series);
// The font the figures use (fonts-dejavu-core); throws if it is missing.
const std::string& plotFont();

}  // namespace hemirad
