#include "src/bench/SceneSize.h"

namespace hemirad {

SceneSize sceneSize(const Scene& scene) {
  SceneSize size;
  size.polygons = scene.polygons().size();
  for (const ScenePolygon& p : scene.polygons()) size.triangles += p.vertices.size() - 2;
  return size;
}

double texelUse(const Atlas& atlas) {
  const double texels = double(atlas.width) * double(atlas.height);
  return texels > 0 ? double(atlas.elements) / texels : 0.0;
}

}  // namespace hemirad
