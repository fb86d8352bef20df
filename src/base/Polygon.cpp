#include "src/base/Polygon.h"

#include <algorithm>
#include <cmath>

namespace hemirad {

glm::dvec3 newellNormal(const Poly3& p) {
  glm::dvec3 n(0.0);
  for (size_t i = 0; i < p.size(); ++i) {
    const glm::dvec3& a = p[i];
    const glm::dvec3& b = p[(i + 1) % p.size()];
    n += glm::dvec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
  }
  return n;
}

double area(const Poly3& p) { return 0.5 * glm::length(newellNormal(p)); }

double signedArea(const Poly2& p) {
  double s = 0;
  for (size_t i = 0; i < p.size(); ++i) {
    const glm::dvec2& a = p[i];
    const glm::dvec2& b = p[(i + 1) % p.size()];
    s += a.x * b.y - b.x * a.y;
  }
  return 0.5 * s;
}

glm::dvec2 centroid(const Poly2& p) {
  double a = 0;
  glm::dvec2 c(0.0), mean(0.0);
  for (size_t i = 0; i < p.size(); ++i) {
    const glm::dvec2& u = p[i];
    const glm::dvec2& w = p[(i + 1) % p.size()];
    double cross = u.x * w.y - w.x * u.y;
    a += cross;
    c += (u + w) * cross;
    mean += u;
  }
  if (std::abs(a) < 1e-300) return p.empty() ? mean : mean / double(p.size());
  return c / (3.0 * a);
}

double planarityError(const Poly3& p) {
  glm::dvec3 n = newellNormal(p);
  double len = glm::length(n);
  if (len == 0) return 0;
  n /= len;
  glm::dvec3 mean(0.0);
  for (auto& v : p) mean += v;
  mean /= double(p.size());
  double e = 0;
  for (auto& v : p) e = std::max(e, std::abs(glm::dot(v - mean, n)));
  return e;
}

bool isConvex(const Poly3& p, const glm::dvec3& normal) {
  for (size_t i = 0; i < p.size(); ++i) {
    const glm::dvec3& a = p[i];
    const glm::dvec3& b = p[(i + 1) % p.size()];
    const glm::dvec3& c = p[(i + 2) % p.size()];
    if (glm::dot(glm::cross(b - a, c - b), normal) < 0) return false;
  }
  return true;
}

Poly2 clipToBox(const Poly2& poly, glm::dvec2 lo, glm::dvec2 hi) {
  Poly2 out = poly;
  // Each half-plane: axis (0 = x, 1 = y), bound, keep side (+1 keeps >= bound, -1 keeps <= bound).
  const struct {
    int axis;
    double bound;
    double side;
  } planes[4] = {{0, lo.x, 1}, {0, hi.x, -1}, {1, lo.y, 1}, {1, hi.y, -1}};
  for (const auto& pl : planes) {
    if (out.empty()) break;
    Poly2 in = std::move(out);
    out.clear();
    for (size_t i = 0; i < in.size(); ++i) {
      const glm::dvec2& a = in[i];
      const glm::dvec2& b = in[(i + 1) % in.size()];
      double da = (a[pl.axis] - pl.bound) * pl.side, db = (b[pl.axis] - pl.bound) * pl.side;
      if (da >= 0) out.push_back(a);
      if ((da >= 0) != (db >= 0)) {
        glm::dvec2 x = a + (b - a) * (da / (da - db));
        x[pl.axis] = pl.bound;  // exact on the boundary
        out.push_back(x);
      }
    }
  }
  return out;
}

Box2 boundingBox(const Poly2& p) {
  Box2 b;
  for (const glm::dvec2& q : p) b.lo = glm::min(b.lo, q), b.hi = glm::max(b.hi, q);
  return b;
}

std::vector<int> triangulate(const Poly3& p, const glm::dvec3& normal) {
  PlaneFrame f = planeFrame(p, normal);
  Poly2 q;
  for (auto& v : p) q.push_back(f.project(v));
  std::vector<int> idx(p.size());
  for (size_t i = 0; i < p.size(); ++i) idx[i] = int(i);
  if (signedArea(q) < 0) std::reverse(idx.begin(), idx.end());
  auto cross = [&](int a, int b, int c) {
    return (q[b].x - q[a].x) * (q[c].y - q[a].y) - (q[b].y - q[a].y) * (q[c].x - q[a].x);
  };
  auto inside = [&](int a, int b, int c, int x) {
    return cross(a, b, x) >= 0 && cross(b, c, x) >= 0 && cross(c, a, x) >= 0;
  };
  std::vector<int> tris;
  while (idx.size() > 3) {
    bool clipped = false;
    for (size_t i = 0; i < idx.size() && !clipped; ++i) {
      int a = idx[(i + idx.size() - 1) % idx.size()], b = idx[i], c = idx[(i + 1) % idx.size()];
      if (cross(a, b, c) <= 0) continue;  // reflex or degenerate corner
      bool ear = true;
      for (int x : idx)
        if (x != a && x != b && x != c && inside(a, b, c, x)) ear = false;
      if (!ear) continue;
      tris.insert(tris.end(), {a, b, c});
      idx.erase(idx.begin() + long(i));
      clipped = true;
    }
    if (!clipped) {  // self-intersecting or numerically flat: fall back to a fan
      for (size_t i = 1; i + 1 < idx.size(); ++i) tris.insert(tris.end(), {idx[0], idx[i], idx[i + 1]});
      idx.clear();
    }
  }
  if (idx.size() == 3) tris.insert(tris.end(), {idx[0], idx[1], idx[2]});
  // Keep the original winding so the front side stays the front side.
  if (signedArea(q) < 0)
    for (size_t t = 0; t < tris.size(); t += 3) std::swap(tris[t + 1], tris[t + 2]);
  return tris;
}

PlaneFrame planeFrame(const Poly3& p, const glm::dvec3& normal) {
  PlaneFrame f;
  f.n = glm::normalize(normal);
  size_t best = 0;
  double bestLen = -1;
  for (size_t i = 0; i < p.size(); ++i) {
    double len = glm::length(p[(i + 1) % p.size()] - p[i]);
    if (len > bestLen) bestLen = len, best = i;
  }
  glm::dvec3 e = p[(best + 1) % p.size()] - p[best];
  f.u = glm::normalize(e - f.n * glm::dot(e, f.n));
  f.v = glm::cross(f.n, f.u);
  f.origin = p[best];
  return f;
}

bool clipSegment(const Poly2& poly, glm::dvec2 a, glm::dvec2 b, double inset, double& t0, double& t1) {
  t0 = 0, t1 = 1;
  const glm::dvec2 d = b - a;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const glm::dvec2 p = poly[i], e = poly[(i + 1) % poly.size()] - p;
    const double len = glm::length(e);
    if (!(len > 0)) continue;
    const glm::dvec2 inward(-e.y / len, e.x / len);
    const double fa = glm::dot(a - p, inward) - inset, fd = glm::dot(d, inward);
    if (fd == 0) {
      if (fa < 0) return false;
      continue;
    }
    const double t = -fa / fd;
    if (fd > 0)
      t0 = std::max(t0, t);
    else
      t1 = std::min(t1, t);
    if (t1 <= t0) return false;
  }
  return true;
}

}  // namespace hemirad
