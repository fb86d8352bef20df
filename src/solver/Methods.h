// `solve --method`: the radiosity methods behind the Solver seam. Progressive refinement and
// stochastic iteration are built; instant radiosity is named so the flag can say which issue brings it.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "src/solver/ProgressiveSolver.h"
#include "src/solver/StochasticSolver.h"

namespace hemirad {

enum class Method { Progressive, Stochastic, Instant };
const char* methodName(Method m);
const std::vector<std::pair<std::string, Method>>& methodNames();
// InputError for a method not built yet, naming the issue that builds it; cheap, so the
// solve command calls it before reading the scene.
void requireBuilt(Method m);
// The solver of method `m` over `state` with that method's settings.
std::unique_ptr<Solver> makeSolver(Method m, SolverState& state, const ProgressiveSettings& progressive,
                                   const StochasticSettings& stochastic);

}  // namespace hemirad
