// The dense reference solution for small scenes: the full element-to-element matrix of exact
// form factors (contour integral from each element's centre to each other element, CGAL
// visibility between centres) solved by Gauss-Seidel. B_i = E_i + rho_i sum_j F_ij B_j.
#pragma once
#include <glm/glm.hpp>
#include <vector>

#include "cpu/ExactVisibility.h"
#include "src/scene/Atlas.h"
#include "src/scene/Scene.h"

namespace hemirad {

struct DenseSolution {
  std::vector<glm::dvec3> B;  // per atlas texel (zero where no element)
  int iterations = 0;
  double change = 0;  // largest relative change in the last sweep
};

constexpr std::size_t kDenseMaxElements = 5000;

// The discrete operator itself: element i is atlas texel texel[i]; F row-major, F[i n + j].
struct DenseSystem {
  std::vector<std::size_t> texel;
  std::vector<float> F;
  std::vector<glm::dvec3> rho, E;
  // (T B)_i = rho_i sum_j F_ij B_j for B per atlas texel; the result per atlas texel (zero where
  // no element). What one application of the stochastic operator estimates (StochasticProbe).
  std::vector<glm::dvec3> transport(const std::vector<glm::dvec3>& B) const;
};

// Throws InputError above kDenseMaxElements elements (N^2 form factors).
DenseSystem buildDense(const Scene& scene, const Atlas& atlas, const cpu::ExactVisibility& visibility);

// Throws InputError above kDenseMaxElements elements (N^2 form factors).
DenseSolution solveDense(const Scene& scene, const Atlas& atlas, const cpu::ExactVisibility& visibility,
                         double tolerance = 1e-6);

}  // namespace hemirad
