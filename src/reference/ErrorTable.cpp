#include "src/reference/ErrorTable.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <functional>

#include "src/scene/Atlas.h"

namespace hemirad {

namespace {

double pixelLuminance(const Image& image, std::size_t p) {
  return luminance(glm::dvec3(image.rgb[3 * p], image.rgb[3 * p + 1], image.rgb[3 * p + 2]));
}

// The relative error of each pixel compared; NaN for one left out.
std::vector<double> relativeErrors(const PixelRegions& regions, const Image& a, const Image& b) {
  std::vector<double> e(regions.polygon.size(), std::nan(""));
  for (std::size_t p = 0; p < e.size(); ++p) {
    const double ref = pixelLuminance(b, p);
    if (regions.polygon[p] != kNoPolygon && ref > 1e-12) e[p] = (pixelLuminance(a, p) - ref) / ref;
  }
  return e;
}

ErrorRow row(const std::string& name, const std::vector<double>& e, const Image& b, const Image& standardError,
             const std::function<bool(std::size_t)>& in) {
  ErrorRow r{name};
  std::vector<double> magnitudes;
  double noise = 0;
  for (std::size_t p = 0; p < e.size(); ++p) {
    if (std::isnan(e[p]) || !in(p)) continue;
    magnitudes.push_back(std::abs(e[p]));
    r.bias += e[p];
    if (!standardError.rgb.empty()) noise += pixelLuminance(standardError, p) / pixelLuminance(b, p);
  }
  r.pixels = magnitudes.size();
  if (r.pixels == 0) return r;
  for (double m : magnitudes) r.meanAbsolute += m;
  r.meanAbsolute /= double(r.pixels), r.bias /= double(r.pixels);
  const std::size_t rank = std::size_t(std::ceil(0.95 * double(r.pixels))) - 1;  // nearest rank
  std::nth_element(magnitudes.begin(), magnitudes.begin() + rank, magnitudes.end());
  r.p95Absolute = magnitudes[rank];
  if (!standardError.rgb.empty()) r.noise = noise / double(r.pixels);
  return r;
}

}  // namespace

std::vector<ErrorRow> errorTable(const Scene& scene, const PixelRegions& regions, const Image& a, const Image& b,
                                 const Image& standardError) {
  const std::vector<double> e = relativeErrors(regions, a, b);
  std::vector<ErrorRow> rows;
  auto add = [&](const std::string& name, const std::function<bool(std::size_t)>& in) {
    rows.push_back(row(name, e, b, standardError, in));
  };
  add(fmt::format("interior (>= {} px from an edge)", PixelRegions::kEdgeReach),
      [&](std::size_t p) { return regions.edgeDistance[p] >= PixelRegions::kEdgeReach; });
  add("edge band (1 px)", [&](std::size_t p) { return regions.edgeDistance[p] == 1; });
  for (int k = 1; k <= PixelRegions::kCreaseReach; ++k)
    add(fmt::format("corner band ({} px)", k), [&regions, k](std::size_t p) { return regions.creaseDistance[p] == k; });
  add(fmt::format("beside a light (1-{} px from its rim)", PixelRegions::kLightReach),
      [&](std::size_t p) { return regions.lightDistance[p] <= PixelRegions::kLightReach; });
  for (std::size_t o = 0; o < scene.objects.size(); ++o)
    add("object " + scene.objects[o].name,
        [&, o](std::size_t p) { return std::size_t(scene.polygons()[regions.polygon[p]].object) == o; });
  add("whole image", [](std::size_t) { return true; });
  return rows;
}

std::string markdown(const std::vector<ErrorRow>& rows) {
  const bool noise = !rows.empty() && rows.front().noise >= 0;
  std::string t = "| region | pixels | mean abs. error | p95 abs. error | bias (signed mean) |";
  t += noise ? " B's noise (mean std. error) |\n|---|---|---|---|---|---|\n" : "\n|---|---|---|---|---|\n";
  for (const ErrorRow& r : rows) {
    if (r.pixels == 0) {  // e.g. no crease in view
      t += fmt::format("| {} | 0 | - | - | - |{}\n", r.region, noise ? " - |" : "");
      continue;
    }
    t += fmt::format("| {} | {} | {:.3f} % | {:.3f} % | {:+.3f} % |", r.region, r.pixels, 100 * r.meanAbsolute,
                     100 * r.p95Absolute, 100 * r.bias);
    t += noise ? fmt::format(" {:.3f} % |\n", 100 * r.noise) : "\n";
  }
  return t;
}

Image errorMap(const PixelRegions& regions, const Image& a, const Image& b, double range) {
  const std::vector<double> e = relativeErrors(regions, a, b);
  Image map{a.width, a.height, std::vector<float>(a.rgb.size(), 0.0f)};
  for (std::size_t p = 0; p < e.size(); ++p) {
    if (std::isnan(e[p])) continue;
    const float s = float(std::min(std::abs(e[p]) / range, 1.0));
    const glm::vec3 c = e[p] > 0 ? glm::vec3(1, 1 - s, 1 - s) : glm::vec3(1 - s, 1 - s, 1);
    for (int k = 0; k < 3; ++k) map.rgb[3 * p + k] = c[k];
  }
  return map;
}

}  // namespace hemirad
