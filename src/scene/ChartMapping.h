// How a chart's surface maps to its chart coordinates (scene units; its texels are squares of the
// atlas's texel size there), the one thing that differs between the two kinds of chart (issue 29):
// a projection along the chart's axis onto one plane frame (src/scene/Charts.h), or per-vertex
// 2D coordinates of its triangles (the input's lightmap UVs, src/scene/InputUv.h; LSCM,
// src/scene/Lscm.h), each triangle mapped by its own affine (barycentric) map. Everything else
// (cutting texels, shooter blocks, atlas coordinates, outputs) goes through these functions.
#pragma once
#include <glm/glm.hpp>
#include <vector>

#include "src/base/Polygon.h"
#include "src/scene/Scene.h"

namespace hemirad {

struct ChartMapping {
  PlaneFrame frame;       // a projection chart's plane (n: its axis)
  bool planar = true;     // members coplanar: pieces lie in the frame's plane
  std::vector<Poly2> uv;  // a UV chart's parts (triangles): their vertices' chart coordinates
  // A cluster of small charts (src/scene/Clusters.h): a UV chart of one cell whose triangles
  // overlap there, each mapped by its own polygon's plane.
  bool clustered = false;

  bool uvMapped() const { return !uv.empty(); }
  // Part k (`part`: its 3D vertices) in chart coordinates.
  Poly2 partInChart(const Poly3& part, std::size_t k) const;
  // Point p on part k in chart coordinates.
  glm::dvec2 toChart(const Poly3& part, std::size_t k, const glm::dvec3& p) const;
  // Chart point q back on the surface of part k, which lies on polygon `on`.
  glm::dvec3 toSurface(const Poly3& part, std::size_t k, const ScenePolygon& on, glm::dvec2 q) const;
  // The surface area of a piece of part k whose chart area is `chartArea`.
  double surfaceArea(const Poly3& part, std::size_t k, const ScenePolygon& on, double chartArea) const;
  // How well p fits part k (a UV chart's triangles): its least barycentric coordinate, >= 0 inside.
  double inside(const Poly3& part, std::size_t k, const glm::dvec3& p) const;
};

// Chart point q on the triangle `tri` whose chart coordinates are `uv` (its affine map).
glm::dvec3 liftTriangle(const Poly3& tri, const Poly2& uv, glm::dvec2 q);

}  // namespace hemirad
