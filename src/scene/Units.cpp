#include "src/scene/Units.h"

#include <cmath>

#include "src/base/Error.h"

namespace hemirad {

void normalizeUnits(Scene& scene) {
  if (scene.polygons().empty()) return;  // validateSolvable says so
  const double diagonal = glm::length(scene.boundsMax() - scene.boundsMin());
  if (!std::isfinite(diagonal) || !(diagonal > 0))
    fail("{}: the scene's size {} is not a finite positive number", scene.path, diagonal);
  for (const Material& m : scene.materials)
    for (int c = 0; c < 3; ++c)
      if (m.emission[c] > kMaxEmission || (m.emission[c] > 0 && m.emission[c] < 1 / kMaxEmission))
        fail(
            "{}: material '{}': emission {:g} is outside the range float radiosity holds ({:g} to {:g}); "
            "scale the scene's emission",
            scene.path, m.name, m.emission[c], 1 / kMaxEmission, kMaxEmission);
  if (diagonal >= kMinDiagonal && diagonal <= kMaxDiagonal) return;
  const double factor = std::ldexp(1.0, -std::ilogb(diagonal));  // diagonal x factor in [1, 2)
  scene.rescale(factor);
  scene.unitScale *= factor;
  scene.warnings.push_back(
      {scene.path, fmt::format("the scene's size {:g} is far from 1: solved in units {:g} times "
                               "the file's (exact: a power of two); outputs are in the file's units",
                               diagonal, factor)});
}

Camera toSceneUnits(const Scene& scene, Camera c) {
  c.eye *= scene.unitScale, c.target *= scene.unitScale;
  return c;
}

Camera toFileUnits(const Scene& scene, Camera c) {
  c.eye /= scene.unitScale, c.target /= scene.unitScale;
  return c;
}

}  // namespace hemirad
