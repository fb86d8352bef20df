// C++ mirror of shaders/hemisphere.glsl (same formulas, double precision) for the CPU
// reference and the tests. Keep the two in step.
#pragma once
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

// Seed 003's hemispherical projection: a direction at angle theta from the normal lands at
// radius sin(theta) in [-1, 1]^2.
inline glm::dvec2 hemiProject(const glm::dvec3& local) {
  double len = glm::length(local);
  return len > 0 ? glm::dvec2(local) / len : glm::dvec2(0.0);
}

// The disc form factor (docs/design.md#form-factor).
inline double discFormFactor(double cosS, double cosR, double r2, double shooterArea) {
  return glm::max(cosS, 0.0) * glm::max(cosR, 0.0) * shooterArea / (3.14159265358979323846 * r2 + shooterArea);
}

}  // namespace hemirad::cpu
