#include "src/solver/Methods.h"

#include <fmt/format.h>

#include <stdexcept>

#include "src/base/Error.h"

namespace hemirad {

const std::vector<std::pair<std::string, Method>>& methodNames() {
  static const std::vector<std::pair<std::string, Method>> names{
      {"progressive", Method::Progressive}, {"stochastic", Method::Stochastic}, {"instant", Method::Instant}};
  return names;
}

const char* methodName(Method m) {
  for (const auto& [name, method] : methodNames())
    if (method == m) return name.c_str();
  return "?";
}

void requireBuilt(Method m) {
  switch (m) {
    case Method::Progressive: return;
    case Method::Stochastic: return;
    case Method::Instant: return;
  }
}

std::unique_ptr<Solver> makeSolver(Method m, SolverState& state, const ProgressiveSettings& progressive,
                                   const StochasticSettings& stochastic) {
  requireBuilt(m);
  if (m == Method::Instant) throw std::logic_error("instant radiosity renders camera images, it has no Solver");
  if (m == Method::Stochastic) return std::make_unique<StochasticSolver>(state, stochastic);
  return std::make_unique<ProgressiveSolver>(state, progressive);
}

}  // namespace hemirad
