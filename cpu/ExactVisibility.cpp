// The only CGAL translation unit: CGAL is slow to compile, so it stays here.
#include "cpu/ExactVisibility.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

namespace hemirad::cpu {

namespace {
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Triangle = K::Triangle_3;
using Segment = K::Segment_3;
using Iterator = std::vector<Triangle>::const_iterator;
using Primitive = CGAL::AABB_triangle_primitive<K, Iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;

Point point(const glm::dvec3& p) { return {p.x, p.y, p.z}; }
}  // namespace

struct ExactVisibility::Impl {
  std::vector<Triangle> triangles;
  std::vector<int> polygonOf;  // per triangle
  Tree tree;
};

ExactVisibility::ExactVisibility(const std::vector<std::vector<glm::dvec3>>& polygons)
    : impl_(std::make_unique<Impl>()) {
  for (size_t p = 0; p < polygons.size(); ++p)
    for (size_t k = 1; k + 1 < polygons[p].size(); ++k) {  // convex: a fan
      impl_->triangles.emplace_back(point(polygons[p][0]), point(polygons[p][k]), point(polygons[p][k + 1]));
      impl_->polygonOf.push_back(int(p));
    }
  impl_->tree.insert(impl_->triangles.cbegin(), impl_->triangles.cend());
  impl_->tree.accelerate_distance_queries();
  impl_->tree.build();
}

ExactVisibility::~ExactVisibility() = default;

std::size_t ExactVisibility::triangles() const { return impl_->triangles.size(); }

bool ExactVisibility::visible(const glm::dvec3& a, int polyA, const glm::dvec3& b, int polyB) const {
  return visible(a, b, [&](int p) { return p == polyA || p == polyB; });
}

bool ExactVisibility::visible(const glm::dvec3& a, const glm::dvec3& b, const std::function<bool(int)>& passes) const {
  Segment s(point(a), point(b));
  if (!impl_->tree.do_intersect(s)) return true;
  // Something is touched: it hides b unless every polygon touched passes.
  std::vector<Tree::Primitive_id> hits;
  impl_->tree.all_intersected_primitives(s, std::back_inserter(hits));
  for (Iterator it : hits)
    if (!passes(impl_->polygonOf[size_t(it - impl_->triangles.cbegin())])) return false;
  return true;
}

}  // namespace hemirad::cpu
