// The item mesh (seed 003 §39.2.1, seed 004 §4.1.4): the scene's polygons as triangles split
// 1-to-4 `level` times, each sub-triangle remembering its polygon. Straight edges under the
// curved hemisphere projection err less on smaller triangles.
#pragma once
#include <cstdint>
#include <vector>

#include "src/scene/Scene.h"

namespace hemirad {

struct ItemVertex {
  float x, y, z;
  std::uint32_t polygon;
};

// Three vertices per triangle, no index buffer. Midpoints are computed from the edge's
// endpoints symmetrically, so neighbours sharing an edge split it at the same point.
std::vector<ItemVertex> buildItemMesh(const Scene& scene, int level);

// The same triangles with each distinct vertex (position and polygon, bitwise) stored once, in
// order of first use, and three indices a triangle: a split mesh shares each vertex between up
// to six triangles, so the item buffer shades a sixth as many vertices.
struct IndexedItemMesh {
  std::vector<ItemVertex> vertices;
  std::vector<std::uint32_t> indices;
};
IndexedItemMesh indexItemMesh(const std::vector<ItemVertex>& triangles);

inline std::size_t itemTriangleCount(const Scene& scene, int level) {
  std::size_t base = 0;
  for (std::size_t id = 0; id < scene.occluderCount(); ++id)
    if (scene.drawn(id)) base += scene.occluder(id).vertices.size() - 2;
  return base << (2 * level);
}

}  // namespace hemirad
