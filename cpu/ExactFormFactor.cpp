#include "cpu/ExactFormFactor.h"

#include <algorithm>
#include <cmath>

namespace hemirad::cpu {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Keeps the part of `poly` with dot(x - p, n) >= 0.
Polygon clipToHalfSpace(const Polygon& poly, const glm::dvec3& p, const glm::dvec3& n) {
  Polygon out;
  for (size_t i = 0; i < poly.size(); ++i) {
    const glm::dvec3& a = poly[i];
    const glm::dvec3& b = poly[(i + 1) % poly.size()];
    double da = glm::dot(a - p, n), db = glm::dot(b - p, n);
    if (da >= 0) out.push_back(a);
    if ((da >= 0) != (db >= 0)) out.push_back(a + (b - a) * (da / (da - db)));
  }
  return out;
}

glm::dvec3 centroid(const Polygon& poly) {
  glm::dvec3 c(0.0);
  for (auto& v : poly) c += v;
  return c / double(poly.size());
}

}  // namespace

double pointToPolygon(const glm::dvec3& p, const glm::dvec3& n, const Polygon& polygon, const glm::dvec3& frontNormal) {
  if (polygon.size() < 3 || glm::dot(p - polygon[0], frontNormal) <= 0) return 0;
  Polygon visible = clipToHalfSpace(polygon, p, n);
  if (visible.size() < 3) return 0;
  double sum = 0;
  for (size_t i = 0; i < visible.size(); ++i) {
    glm::dvec3 a = glm::normalize(visible[i] - p), b = glm::normalize(visible[(i + 1) % visible.size()] - p);
    glm::dvec3 c = glm::cross(a, b);
    double s = glm::length(c);
    if (s == 0) continue;
    sum += std::atan2(s, glm::dot(a, b)) * glm::dot(c, n) / s;
  }
  // Counter-clockwise around frontNormal seen from the front, the contour runs clockwise around
  // the direction to p, so the sum is negative.
  return std::max(0.0, -sum / (2 * kPi));
}

ElementFormFactor pointToElement(const glm::dvec3& p, const glm::dvec3& n, const Polygon& element,
                                 const glm::dvec3& frontNormal, const VisibleFn& visible, int strata) {
  ElementFormFactor r;
  double unoccluded = pointToPolygon(p, n, element, frontNormal);
  if (unoccluded <= 0) return r;
  bool all = visible(centroid(element));
  for (const auto& v : element) all = all && visible(glm::mix(v, centroid(element), 1e-6));
  if (all) return {unoccluded, 0.0};

  // Stratify the element's plane into strata x strata cells over its bounding rectangle.
  glm::dvec3 u = glm::normalize(element[1] - element[0]), w = glm::cross(frontNormal, u);
  double u0 = 1e300, u1 = -1e300, w0 = 1e300, w1 = -1e300;
  for (auto& v : element) {
    double a = glm::dot(v - element[0], u), b = glm::dot(v - element[0], w);
    u0 = std::min(u0, a), u1 = std::max(u1, a), w0 = std::min(w0, b), w1 = std::max(w1, b);
  }
  std::vector<double> cellF(size_t(strata * strata), 0.0);
  std::vector<int> cellV(size_t(strata * strata), -1);
  for (int j = 0; j < strata; ++j)
    for (int i = 0; i < strata; ++i) {
      // The cell is the element clipped to the rectangle [ua, ub] x [wa, wb].
      double ua = u0 + (u1 - u0) * i / strata, ub = u0 + (u1 - u0) * (i + 1) / strata;
      double wa = w0 + (w1 - w0) * j / strata, wb = w0 + (w1 - w0) * (j + 1) / strata;
      Polygon cell = element;
      cell = clipToHalfSpace(cell, element[0] + ua * u, u);
      cell = clipToHalfSpace(cell, element[0] + ub * u, -u);
      cell = clipToHalfSpace(cell, element[0] + wa * w, w);
      cell = clipToHalfSpace(cell, element[0] + wb * w, -w);
      if (cell.size() < 3) continue;
      size_t k = size_t(j * strata + i);
      cellF[k] = pointToPolygon(p, n, cell, frontNormal);
      cellV[k] = visible(centroid(cell)) ? 1 : 0;
      r.value += cellV[k] * cellF[k];
    }
  for (int j = 0; j < strata; ++j)
    for (int i = 0; i < strata; ++i) {
      size_t k = size_t(j * strata + i);
      if (cellV[k] < 0) continue;
      bool edge = false;
      for (auto [di, dj] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
        int a = i + di, b = j + dj;
        if (a < 0 || b < 0 || a >= strata || b >= strata) continue;
        int other = cellV[size_t(b * strata + a)];
        edge = edge || (other >= 0 && other != cellV[k]);
      }
      if (edge) r.bound += cellF[k];
    }
  return r;
}

void gaussLegendre(int count, std::vector<double>& nodes, std::vector<double>& weights) {
  nodes.assign(size_t(count), 0.0);
  weights.assign(size_t(count), 0.0);
  for (int i = 0; i < count; ++i) {
    double x = std::cos(kPi * (i + 0.75) / (count + 0.5)), dp = 0;
    for (int iter = 0; iter < 100; ++iter) {
      double p0 = 1, p1 = x;
      for (int k = 2; k <= count; ++k) {
        double pk = ((2 * k - 1) * x * p1 - (k - 1) * p0) / k;
        p0 = p1, p1 = pk;
      }
      dp = count * (x * p1 - p0) / (x * x - 1);
      double dx = p1 / dp;
      x -= dx;
      if (std::abs(dx) < 1e-15) break;
    }
    nodes[size_t(i)] = 0.5 * (1 - x);
    weights[size_t(i)] = 1.0 / ((1 - x * x) * dp * dp);  // 2/((1-x^2)P'^2), halved for [0, 1]
  }
}

double rectangleToPolygon(const glm::dvec3& origin, const glm::dvec3& u, const glm::dvec3& v, double w, double h,
                          const Polygon& target, const glm::dvec3& targetNormal) {
  std::vector<double> x, wx;
  gaussLegendre(12, x, wx);
  glm::dvec3 n = glm::normalize(glm::cross(u, v));
  // Panels graded geometrically toward v = 0 (the edge a neighbour may share) and, along u,
  // toward both ends (the corners of that edge), where the integrand is not smooth.
  std::vector<double> vCuts{0.0}, uCuts{0.0};
  for (int k = 24; k >= 0; --k) vCuts.push_back(h * std::pow(0.25, k));
  for (int k = 24; k >= 1; --k) uCuts.push_back(0.5 * w * std::pow(0.25, k));
  for (int k = int(uCuts.size()) - 1; k >= 0; --k) uCuts.push_back(w - uCuts[size_t(k)]);
  double sum = 0;
  for (size_t c = 0; c + 1 < vCuts.size(); ++c)
    for (size_t j = 0; j < x.size(); ++j) {
      double t = vCuts[c] + (vCuts[c + 1] - vCuts[c]) * x[j], row = 0;
      for (size_t d = 0; d + 1 < uCuts.size(); ++d)
        for (size_t i = 0; i < x.size(); ++i) {
          double s = uCuts[d] + (uCuts[d + 1] - uCuts[d]) * x[i];
          row += wx[i] * (uCuts[d + 1] - uCuts[d]) * pointToPolygon(origin + u * s + v * t, n, target, targetNormal);
        }
      sum += wx[j] * (vCuts[c + 1] - vCuts[c]) * row;
    }
  return sum / (w * h);
}

}  // namespace hemirad::cpu
