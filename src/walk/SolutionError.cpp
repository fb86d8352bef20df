#include "src/walk/SolutionError.h"

#include <cmath>

namespace hemirad {

double relativeRmsError(const Scene& scene, const Atlas& atlas, const std::vector<glm::vec4>& B,
                        const std::vector<glm::vec4>& reference) {
  double squares = 0, mean = 0, area = 0;
  for (std::size_t t = 0; t < B.size(); ++t) {
    if (atlas.polygonOf[t] == kNoPolygon) continue;
    if (scene.materials[std::size_t(scene.polygons()[atlas.polygonOf[t]].material)].emissive()) continue;
    const double A = atlas.positionArea[t].w, r = luminance(glm::dvec3(reference[t]));
    const double e = luminance(glm::dvec3(B[t])) - r;
    squares += A * e * e;
    mean += A * r;
    area += A;
  }
  return mean > 0 ? std::sqrt(squares / area) / (mean / area) : 0.0;
}

}  // namespace hemirad
