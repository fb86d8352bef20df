#include "src/base/MinAreaRect.h"

#include <algorithm>

namespace hemirad {

namespace {
double cross(glm::dvec2 o, glm::dvec2 a, glm::dvec2 b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

double boxArea(const std::vector<glm::dvec2>& points) {
  glm::dvec2 lo(1e300), hi(-1e300);
  for (glm::dvec2 p : points) lo = glm::min(lo, p), hi = glm::max(hi, p);
  return points.empty() ? 0 : (hi.x - lo.x) * (hi.y - lo.y);
}
}  // namespace

std::vector<glm::dvec2> convexHull(std::vector<glm::dvec2> p) {
  std::sort(p.begin(), p.end(), [](glm::dvec2 a, glm::dvec2 b) { return a.x != b.x ? a.x < b.x : a.y < b.y; });
  p.erase(std::unique(p.begin(), p.end()), p.end());
  if (p.size() < 3) return p;
  std::vector<glm::dvec2> h(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {  // lower chain
    while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i-- > 0;) {  // upper chain
    while (k >= t && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  h.resize(k - 1);
  return h;
}

// Calipers: for edge i the support points farthest along it (right), against it (left) and
// from it (top) only move forward as i does, so the whole sweep is linear in the hull.
MinAreaRect minAreaRect(const std::vector<glm::dvec2>& points) {
  const std::vector<glm::dvec2> h = convexHull(points);
  MinAreaRect best{{1, 0}, boxArea(points)};
  const std::size_t n = h.size();
  if (n < 3) return best;
  best.area = 1e300;
  std::size_t right = 0, top = 0, left = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const glm::dvec2 e = glm::normalize(h[(i + 1) % n] - h[i]), normal(-e.y, e.x);
    auto along = [&](std::size_t k) { return glm::dot(h[k % n] - h[i], e); };
    auto up = [&](std::size_t k) { return glm::dot(h[k % n] - h[i], normal); };
    if (i == 0) right = top = 1;
    right = std::max(right, i + 1), top = std::max(top, right);
    while (along(right + 1) > along(right)) ++right;
    while (up(top + 1) > up(top)) ++top;
    if (i == 0) left = top;
    left = std::max(left, top);
    while (along(left + 1) < along(left)) ++left;
    const double area = (along(right) - along(left)) * up(top);
    if (area < best.area) best = {e, area};
  }
  return best;
}

}  // namespace hemirad
