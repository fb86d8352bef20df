#include "src/output/Plot.h"

#include <OpenImageIO/imagebufalgo.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "src/base/AtomicFile.h"
#include "src/base/Error.h"

namespace hemirad {

namespace OIIO = OIIO_NAMESPACE;

const std::string& plotFont() {
  static const std::string font = [] {
    for (const char* f : {"/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf", "/usr/share/fonts/TTF/DejaVuSans.ttf"})
      if (std::filesystem::exists(f)) return std::string(f);
    throw InputError("figures need the DejaVu Sans font (Debian package fonts-dejavu-core)");
  }();
  return font;
}

namespace {

// A colour-blind-safe palette (Okabe-Ito).
const float kPalette[][3] = {{0.0f, 0.447f, 0.698f}, {0.835f, 0.369f, 0.0f}, {0.0f, 0.620f, 0.451f},
                             {0.800f, 0.475f, 0.655f}, {0.337f, 0.706f, 0.914f}, {0.902f, 0.624f, 0.0f},
                             {0.941f, 0.894f, 0.259f}, {0.0f, 0.0f, 0.0f}};

// Round tick steps (1, 2, 5 x 10^k) giving about `count` ticks over [lo, hi].
std::vector<double> ticks(double lo, double hi, int count) {
  double raw = (hi - lo) / count, mag = std::pow(10.0, std::floor(std::log10(raw)));
  double step = mag * (raw / mag < 1.5 ? 1 : raw / mag < 3.5 ? 2 : raw / mag < 7.5 ? 5 : 10);
  std::vector<double> t;
  for (double v = std::ceil(lo / step) * step; v <= hi + step * 1e-9; v += step) t.push_back(std::abs(v) < step * 1e-9 ? 0 : v);
  return t;
}

std::string label(double v) { return fmt::format("{:.6g}", v); }

// Series: 2-pixel lines, square markers, legend top right (x1, y0: the plot area's corner).
template <class Px, class Py>
void drawSeries(OIIO::ImageBuf& img, const std::vector<PlotSeries>& series, const Px& px, const Py& py, int x1, int y0,
                const std::string& font) {
  const float black[3] = {0, 0, 0};
  for (size_t k = 0; k < series.size(); ++k) {
    OIIO::cspan<float> c(kPalette[k % 8], 3);
    const PlotSeries& s = series[k];
    for (size_t i = 0; i < s.x.size(); ++i) {
      int ax = px(s.x[i]), ay = py(s.y[i]);
      OIIO::ImageBufAlgo::render_box(img, ax - 4, ay - 4, ax + 4, ay + 4, c, true);
      if (i + 1 < s.x.size())
        for (int d = -1; d <= 1; ++d)
          OIIO::ImageBufAlgo::render_line(img, ax, ay + d, px(s.x[i + 1]), py(s.y[i + 1]) + d, c);
    }
    int ly = y0 + 24 + int(k) * 26;
    OIIO::ImageBufAlgo::render_box(img, x1 - 300, ly - 12, x1 - 280, ly + 2, c, true);
    OIIO::ImageBufAlgo::render_text(img, x1 - 270, ly + 2, s.label, 18, font, black);
  }
}

}  // namespace

void writeLinePlot(const std::string& path, const PlotSpec& spec, const std::vector<PlotSeries>& series) {
  const std::string& font = plotFont();
  OIIO::ImageBuf img(OIIO::ImageSpec(spec.width, spec.height, 3, OIIO::TypeDesc::FLOAT));
  const float white[3] = {1, 1, 1}, black[3] = {0, 0, 0}, grid[3] = {0.88f, 0.88f, 0.88f};
  OIIO::ImageBufAlgo::fill(img, white);
  const int left = 110, right = 30, top = 84, bottom = 90;
  const int x0 = left, x1 = spec.width - right, y0 = top, y1 = spec.height - bottom;

  double xlo = 1e300, xhi = -1e300, ylo = 1e300, yhi = -1e300;
  auto ty = [&](double y) { return spec.logY ? std::log10(std::max(y, 1e-12)) : y; };
  for (const auto& s : series)
    for (size_t i = 0; i < s.x.size(); ++i) {
      xlo = std::min(xlo, s.x[i]), xhi = std::max(xhi, s.x[i]);
      ylo = std::min(ylo, ty(s.y[i])), yhi = std::max(yhi, ty(s.y[i]));
    }
  if (xhi <= xlo) xhi = xlo + 1;
  if (yhi <= ylo) yhi = ylo + (spec.logY ? 1 : std::max(1e-6, std::abs(ylo) * 0.1));
  double pad = (yhi - ylo) * 0.08;
  ylo -= pad, yhi += pad;
  if (spec.logY) ylo = std::floor(ylo), yhi = std::ceil(yhi);
  auto px = [&](double x) { return int(std::lround(x0 + (x - xlo) / (xhi - xlo) * (x1 - x0))); };
  auto py = [&](double y) { return int(std::lround(y1 - (ty(y) - ylo) / (yhi - ylo) * (y1 - y0))); };
  auto pyt = [&](double t) { return int(std::lround(y1 - (t - ylo) / (yhi - ylo) * (y1 - y0))); };

  // Grid, ticks and tick labels.
  std::vector<double> xt = ticks(xlo, xhi, 8), yt;
  if (spec.logY)
    for (double e = ylo; e <= yhi + 1e-9; ++e) yt.push_back(e);
  else
    yt = ticks(ylo, yhi, 6);
  for (double t : xt) {
    OIIO::ImageBufAlgo::render_line(img, px(t), y0, px(t), y1, grid);
    OIIO::ImageBufAlgo::render_text(img, px(t) - 8, y1 + 26, label(t), 18, font, black);
  }
  for (double t : yt) {
    OIIO::ImageBufAlgo::render_line(img, x0, pyt(t), x1, pyt(t), grid);
    std::string s = spec.logY ? fmt::format("1e{:g}", t) : label(t);
    OIIO::ImageBufAlgo::render_text(img, 10, pyt(t) + 6, s, 18, font, black);
  }
  OIIO::ImageBufAlgo::render_box(img, x0, y0, x1, y1, black);
  OIIO::ImageBufAlgo::render_text(img, x0, 34, spec.title, 24, font, black);
  OIIO::ImageBufAlgo::render_text(img, (x0 + x1) / 2 - int(spec.xLabel.size()) * 5, spec.height - 25, spec.xLabel, 20,
                                  font, black);
  OIIO::ImageBufAlgo::render_text(img, 10, y0 - 14, spec.yLabel, 18, font, black);

  drawSeries(img, series, px, py, x1, y0, font);
  writeAtomically(path, [&](const std::string& tmp) {
    if (!img.write(tmp, OIIO::TypeDesc::UINT8)) fail("{}: cannot write: {}", path, img.geterror());
  });
}

}  // namespace hemirad
