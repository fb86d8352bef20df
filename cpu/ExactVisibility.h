// Exact visibility between points on the scene's polygons: a CGAL AABB tree over the original
// polygons (not the item mesh), segment queries with exact predicates (Epick).
#pragma once
#include <functional>
#include <glm/glm.hpp>
#include <memory>
#include <vector>

namespace hemirad::cpu {

class ExactVisibility {
 public:
  // polygons[i]: planar convex polygon i (any winding: every face occludes from both sides).
  explicit ExactVisibility(const std::vector<std::vector<glm::dvec3>>& polygons);
  ~ExactVisibility();
  ExactVisibility(const ExactVisibility&) = delete;
  ExactVisibility& operator=(const ExactVisibility&) = delete;

  // True when the segment from a (on polygon polyA) to b (on polygon polyB) meets no other
  // polygon. Hits on polyA and polyB themselves never count, so points on shared edges and
  // coplanar neighbours do not shadow themselves; a segment that touches another polygon,
  // even grazing its edge, counts as hidden.
  bool visible(const glm::dvec3& a, int polyA, const glm::dvec3& b, int polyB) const;
  // The same with the polygons whose hits do not count named by `passes` (a polygon id -> bool).
  bool visible(const glm::dvec3& a, const glm::dvec3& b, const std::function<bool(int)>& passes) const;
  std::size_t triangles() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace hemirad::cpu
