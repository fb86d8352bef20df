// The unbiasedness probe of stochastic iteration: applies the random transport operator T* to
// one fixed B many times, each with other draws (iteration keys 1..N), and keeps per texel the
// sample mean and variance of (T* B), to be compared with the dense solver's T B
// (DenseSystem::transport): E[T* B] = T B is what makes the running mean converge.
#pragma once
#include <glm/glm.hpp>
#include <vector>

#include "src/solver/StochasticSolver.h"

namespace hemirad {

struct OperatorSamples {
  std::size_t applications = 0;
  std::vector<glm::dvec3> mean, variance;  // per atlas texel; sample variance (n - 1)
  std::vector<double> power;               // per application: sum over elements of luminance(T* B) x area
};

// `B` per atlas texel (rgb); `settings` the solver's (seed, shooters, item buffer).
OperatorSamples sampleOperator(SolverState& state, const StochasticSettings& settings, const std::vector<glm::vec4>& B,
                               std::size_t applications);

}  // namespace hemirad
