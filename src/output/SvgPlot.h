// Log-log line plots as SVG: vector figures for papers (the PNG plots of Plot.h are for the
// validation pages). Decade ticks, axis labels, a legend; plain SVG 1.1, no dependency.
#pragma once
#include <string>
#include <vector>

#include "src/output/Plot.h"

namespace hemirad {

// Points with x <= 0 or y <= 0 are left out (no logarithm).
void writeLogLogSvg(const std::string& path, const PlotSpec& spec, const std::vector<PlotSeries>& series);

}  // namespace hemirad
