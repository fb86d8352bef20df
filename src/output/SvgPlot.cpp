#include "src/output/SvgPlot.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "src/base/AtomicFile.h"
#include "src/base/Error.h"

namespace hemirad {

namespace {

constexpr const char* kColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#8c564b"};
constexpr double kLeft = 80, kRight = 20, kTop = 40, kBottom = 60;

struct Range {
  double lo = std::numeric_limits<double>::infinity(), hi = -std::numeric_limits<double>::infinity();
  void add(double v) { lo = std::min(lo, std::floor(std::log10(v))), hi = std::max(hi, std::ceil(std::log10(v))); }
  double span() const { return std::max(hi - lo, 1.0); }
};

std::string escape(const std::string& s) {
  std::string out;
  for (char c : s) out += c == '<' ? "&lt;" : c == '>' ? "&gt;" : c == '&' ? "&amp;" : std::string(1, c);
  return out;
}

// Decade grid lines and labels on both axes.
std::string axes(const PlotSpec& spec, const Range& x, const Range& y, double w, double h) {
  std::string out = fmt::format(R"svg(<rect x="{}" y="{}" width="{}" height="{}" fill="none" stroke="black"/>)svg""\n",
                                kLeft, kTop, w, h);
  for (double d = x.lo; d <= x.lo + x.span(); ++d) {
    const double px = kLeft + (d - x.lo) / x.span() * w;
    out += fmt::format(R"svg(<line x1="{0}" y1="{1}" x2="{0}" y2="{2}" stroke="#ddd"/><text x="{0}" y="{3}" text-anchor="middle">1e{4}</text>)svg""\n",
                       px, kTop, kTop + h, kTop + h + 18, int(d));
  }
  for (double d = y.lo; d <= y.lo + y.span(); ++d) {
    const double py = kTop + h - (d - y.lo) / y.span() * h;
    out += fmt::format(R"svg(<line x1="{0}" y1="{1}" x2="{2}" y2="{1}" stroke="#ddd"/><text x="{3}" y="{4}" text-anchor="end">1e{5}</text>)svg""\n",
                       kLeft, py, kLeft + w, kLeft - 6, py + 4, int(d));
  }
  out += fmt::format(R"svg(<text x="{}" y="{}" text-anchor="middle" font-size="16">{}</text>)svg""\n", kLeft + w / 2, 24, escape(spec.title));
  out += fmt::format(R"svg(<text x="{}" y="{}" text-anchor="middle">{}</text>)svg""\n", kLeft + w / 2, kTop + h + 42, escape(spec.xLabel));
  out += fmt::format(R"svg(<text transform="translate(20,{}) rotate(-90)" text-anchor="middle">{}</text>)svg""\n", kTop + h / 2,
                     escape(spec.yLabel));
  return out;
}

}  // namespace

void writeLogLogSvg(const std::string& path, const PlotSpec& spec, const std::vector<PlotSeries>& series) {
  Range x, y;
  for (const PlotSeries& s : series)
    for (std::size_t i = 0; i < s.x.size(); ++i)
      if (s.x[i] > 0 && s.y[i] > 0) x.add(s.x[i]), y.add(s.y[i]);
  if (!std::isfinite(x.lo) || !std::isfinite(y.lo)) fail("{}: no positive points to plot", path);
  const double w = spec.width - kLeft - kRight, h = spec.height - kTop - kBottom;
  std::string svg = fmt::format(R"svg(<svg xmlns="http://www.w3.org/2000/svg" width="{}" height="{}" font-family="DejaVu Sans, sans-serif" font-size="12">)svg""\n",
                                spec.width, spec.height);
  svg += axes(spec, x, y, w, h);
  for (std::size_t k = 0; k < series.size(); ++k) {
    std::string points;
    for (std::size_t i = 0; i < series[k].x.size(); ++i)
      if (series[k].x[i] > 0 && series[k].y[i] > 0)
        points += fmt::format("{:.1f},{:.1f} ", kLeft + (std::log10(series[k].x[i]) - x.lo) / x.span() * w,
                              kTop + h - (std::log10(series[k].y[i]) - y.lo) / y.span() * h);
    const char* colour = kColours[k % std::size(kColours)];
    svg += fmt::format(R"svg(<polyline fill="none" stroke="{}" stroke-width="2" points="{}"/>)svg""\n", colour, points);
    svg += fmt::format(R"svg(<line x1="{0}" y1="{1}" x2="{2}" y2="{1}" stroke="{3}" stroke-width="2"/><text x="{4}" y="{5}">{6}</text>)svg""\n",
                       kLeft + w - 170, kTop + 16 + 18 * k, kLeft + w - 145, colour, kLeft + w - 140, kTop + 20 + 18 * k,
                       escape(series[k].label));
  }
  writeTextFile(path, svg + "</svg>\n");
}

}  // namespace hemirad
