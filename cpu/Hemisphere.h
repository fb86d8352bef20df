// C++ mirror of shaders/hemisphere.glsl (same formulas, double precision) for the CPU
// reference and the tests. Keep the two in step.
#pragma once
#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>

namespace hemirad::cpu {

// Orthonormal basis (t, b) around unit n (Duff et al. 2017).
inline void shooterBasis(const glm::dvec3& n, glm::dvec3& t, glm::dvec3& b) {
  double s = n.z >= 0 ? 1.0 : -1.0;
  double a = -1.0 / (s + n.z);
  double c = n.x * n.y * a;
  t = {1.0 + s * n.x * n.x * a, s * c, -s * n.x};
  b = {c, s + n.y * n.y * a, -n.y};
}

inline glm::dvec3 shooterLocal(const glm::dvec3& p, const glm::dvec3& origin, const glm::dvec3& n) {
  glm::dvec3 t, b, d = p - origin;
  shooterBasis(n, t, b);
  return {glm::dot(d, t), glm::dot(d, b), glm::dot(d, n)};
}

// Seed 003's hemispherical projection, the orthographic (Nusselt) map: a direction at angle
// theta from the normal lands at radius sin(theta) in [-1, 1]^2.
inline glm::dvec2 hemiProject(const glm::dvec3& local) {
  double len = glm::length(local);
  return len > 0 ? glm::dvec2(local) / len : glm::dvec2(0.0);
}

// Its inverse; outside the disc the nearest horizon direction.
inline glm::dvec3 hemiDirection(const glm::dvec2& ndc) {
  double r2 = glm::dot(ndc, ndc);
  return r2 < 1 ? glm::dvec3(ndc, std::sqrt(1 - r2)) : glm::dvec3(ndc / std::sqrt(r2), 0.0);
}

inline glm::dvec3 unitDirection(const glm::dvec3& local) {
  double len = glm::length(local);
  return len > 0 ? local / len : glm::dvec3(0, 0, 1);
}

// Conformal (true stereographic, = paraboloid): r = tan(theta / 2).
inline glm::dvec2 conformalProject(const glm::dvec3& local) {
  glm::dvec3 u = unitDirection(local);
  return glm::dvec2(u) / std::max(1 + u.z, 1e-6);
}
inline glm::dvec3 conformalDirection(const glm::dvec2& ndc) {
  double r2 = glm::dot(ndc, ndc);
  return r2 < 1 ? glm::dvec3(2.0 * ndc, 1 - r2) / (1 + r2) : glm::dvec3(ndc / std::sqrt(r2), 0.0);
}

// Lambert's equal-area map: r = sqrt(2) sin(theta / 2).
inline glm::dvec2 equalAreaProject(const glm::dvec3& local) {
  glm::dvec3 u = unitDirection(local);
  return glm::dvec2(u) / std::sqrt(std::max(1 + u.z, 1e-12));
}
inline glm::dvec3 equalAreaDirection(const glm::dvec2& ndc) {
  double r2 = glm::dot(ndc, ndc);
  return r2 < 1 ? glm::dvec3(ndc * std::sqrt(2 - r2), 1 - r2) : glm::dvec3(ndc / std::sqrt(r2), 0.0);
}

// The hemicube: face f's coordinates (a, b, c) of a shooter-frame point, looking along +c.
// Faces: +z (top), +x, -x, +y, -y.
inline glm::dvec3 cubeFace(const glm::dvec3& l, int face) {
  if (face == 0) return l;
  if (face == 1) return {l.y, l.z, l.x};
  if (face == 2) return {-l.y, l.z, -l.x};
  if (face == 3) return {-l.x, l.z, l.y};
  return {l.x, l.z, -l.y};
}
inline int cubeFaceOf(const glm::dvec3& l) {
  glm::dvec3 a = glm::abs(l);
  if (l.z >= a.x && l.z >= a.y) return 0;
  if (a.x >= a.y) return l.x >= 0 ? 1 : 2;
  return l.y >= 0 ? 3 : 4;
}
// The shooter-frame direction through point ndc of face f (the inverse of cubeFace, c = 1).
inline glm::dvec3 cubeDirection(const glm::dvec2& ndc, int face) {
  glm::dvec3 f(ndc, 1.0);
  if (face == 0) return f;
  if (face == 1) return {f.z, f.x, f.y};
  if (face == 2) return {-f.z, -f.x, f.y};
  if (face == 3) return {-f.x, f.z, f.y};
  return {f.x, -f.z, f.y};
}

// The disc form factor (docs/design.md#form-factor).
inline double discFormFactor(double cosS, double cosR, double r2, double shooterArea) {
  return glm::max(cosS, 0.0) * glm::max(cosR, 0.0) * shooterArea / (3.14159265358979323846 * r2 + shooterArea);
}

}  // namespace hemirad::cpu
