// What a bench row says about its scene's size beside the element count: the polygons, the
// triangles they make (a convex n-gon is n - 2, whatever the item mesh's level), and the texel
// use, the share of the atlas's texels that hold an element (the charts' empty cells and the
// packing's gaps are the rest; src/scene/AtlasUse.h).
#pragma once
#include <cstddef>

#include "src/scene/Atlas.h"
#include "src/scene/Scene.h"

namespace hemirad {

struct SceneSize {
  std::size_t polygons = 0, triangles = 0;
};

SceneSize sceneSize(const Scene& scene);
double texelUse(const Atlas& atlas);  // elements / (width x height); 0 for an empty atlas

}  // namespace hemirad
