#include "src/validate/DenseSolver.h"

#include <tbb/parallel_for.h>

#include <cmath>

#include "cpu/ExactFormFactor.h"
#include "src/base/Error.h"

namespace hemirad {

DenseSystem buildDense(const Scene& scene, const Atlas& atlas, const cpu::ExactVisibility& visibility) {
  DenseSystem sys;
  std::vector<std::size_t>& texel = sys.texel;
  for (std::size_t t = 0; t < atlas.polygonOf.size(); ++t)
    if (atlas.polygonOf[t] != kNoPolygon) texel.push_back(t);
  const std::size_t n = texel.size();
  if (n > kDenseMaxElements)
    fail("--solution needs a dense {} x {} form-factor matrix; use at most {} elements (--elements)", n, n,
         kDenseMaxElements);

  std::vector<std::vector<Poly3>> shape(n);
  std::vector<glm::dvec3> centre(n), normal(n), &rho = sys.rho, &E = sys.E;
  rho.resize(n), E.resize(n);
  std::vector<int> polygon(n), chart(n);
  for (std::size_t i = 0; i < n; ++i) {
    std::size_t t = texel[i];
    polygon[i] = int(atlas.polygonOf[t]);
    chart[i] = int(atlas.chartAt(t));
    shape[i] = atlas.elementShape(scene, int(t % atlas.width), int(t / atlas.width));
    centre[i] = glm::dvec3(atlas.positionArea[t]);
    const ScenePolygon& p = scene.polygons()[size_t(polygon[i])];
    normal[i] = glm::normalize(glm::dvec3(atlas.normalOf[t]));
    rho[i] = scene.materials[p.material].reflectance;
    E[i] = scene.materials[p.material].emission;
  }
  // Row i: form factors from element i's centre to every element j.
  std::vector<float>& F = sys.F;
  F.assign(n * n, 0.0f);
  tbb::parallel_for(std::size_t(0), n, [&](std::size_t i) {
    for (std::size_t j = 0; j < n; ++j) {
      if (chart[i] == chart[j]) continue;
      if (!cpu::facing(centre[j], normal[j], centre[i], normal[i])) continue;
      if (!visibility.visible(centre[i], polygon[i], centre[j], polygon[j])) continue;
      double f = 0;  // linear in the shape: the pieces' sum is the element's
      for (const Poly3& piece : shape[j])
        f += cpu::pointToPolygon(centre[i], normal[i], piece, glm::normalize(newellNormal(piece)));
      F[i * n + j] = float(f);
    }
  });
  return sys;
}

std::vector<glm::dvec3> DenseSystem::transport(const std::vector<glm::dvec3>& B) const {
  const std::size_t n = texel.size();
  std::vector<glm::dvec3> out(B.size(), glm::dvec3(0.0));
  for (std::size_t i = 0; i < n; ++i) {
    glm::dvec3 gathered(0.0);
    for (std::size_t j = 0; j < n; ++j) gathered += double(F[i * n + j]) * B[texel[j]];
    out[texel[i]] = rho[i] * gathered;
  }
  return out;
}

DenseSolution solveDense(const Scene& scene, const Atlas& atlas, const cpu::ExactVisibility& visibility,
                         double tolerance) {
  const DenseSystem sys = buildDense(scene, atlas, visibility);
  const std::vector<std::size_t>& texel = sys.texel;
  const std::vector<float>& F = sys.F;
  const std::vector<glm::dvec3>&rho = sys.rho, &E = sys.E;
  const std::size_t n = texel.size();
  DenseSolution out;
  std::vector<glm::dvec3> B = E;
  for (out.iterations = 1; out.iterations <= 10000; ++out.iterations) {
    out.change = 0;
    for (std::size_t i = 0; i < n; ++i) {
      glm::dvec3 gathered(0.0);
      const float* row = &F[i * n];
      for (std::size_t j = 0; j < n; ++j)
        if (row[j] != 0.0f) gathered += double(row[j]) * B[j];
      glm::dvec3 next = E[i] + rho[i] * gathered;
      for (int c = 0; c < 3; ++c)
        if (next[c] > 0) out.change = std::max(out.change, std::abs(next[c] - B[i][c]) / next[c]);
      B[i] = next;
    }
    if (out.change < tolerance) break;
  }
  out.B.assign(atlas.polygonOf.size(), glm::dvec3(0.0));
  for (std::size_t i = 0; i < n; ++i) out.B[texel[i]] = B[i];
  return out;
}

}  // namespace hemirad
