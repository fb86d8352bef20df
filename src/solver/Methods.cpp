#include "src/solver/Methods.h"

#include <fmt/format.h>

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
    case Method::Stochastic:
      throw InputError("--method stochastic is not built yet (issue 15: stochastic iteration radiosity)");
    case Method::Instant: throw InputError("--method instant is not built yet (issue 16: instant radiosity)");
  }
}

std::unique_ptr<Solver> makeSolver(Method m, SolverState& state, const ProgressiveSettings& settings) {
  requireBuilt(m);
  return std::make_unique<ProgressiveSolver>(state, settings);
}

}  // namespace hemirad
