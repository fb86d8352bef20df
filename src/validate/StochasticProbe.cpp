#include "src/validate/StochasticProbe.h"

namespace hemirad {

OperatorSamples sampleOperator(SolverState& state, const StochasticSettings& settings, const std::vector<glm::vec4>& B,
                               std::size_t applications) {
  StochasticSolver solver(state, settings);
  const Atlas& atlas = state.atlas;
  const std::size_t n = B.size();
  OperatorSamples out;
  out.applications = applications;
  out.mean.assign(n, glm::dvec3(0.0));
  std::vector<glm::dvec3> m2(n, glm::dvec3(0.0));  // Welford: sums of squared deviations
  for (std::size_t k = 1; k <= applications; ++k) {
    state.restore(B, B);
    solver.applyOperator(std::uint32_t(k));
    const std::vector<glm::vec4> TB = state.readRadiosity();
    double power = 0;
    for (std::size_t t = 0; t < n; ++t) {
      if (atlas.polygonOf[t] == kNoPolygon) continue;
      const glm::dvec3 x(TB[t]);
      const glm::dvec3 d = x - out.mean[t];
      out.mean[t] += d / double(k);
      m2[t] += d * (x - out.mean[t]);
      power += luminance(x) * atlas.positionArea[t].w;
    }
    out.power.push_back(power);
  }
  out.variance.resize(n);
  for (std::size_t t = 0; t < n; ++t)
    out.variance[t] = applications > 1 ? m2[t] / double(applications - 1) : glm::dvec3(0.0);
  return out;
}

}  // namespace hemirad
