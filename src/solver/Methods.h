// `solve --method`: the radiosity methods. Progressive refinement and stochastic iteration are
// Solvers over the atlas; instant radiosity (seed 002) renders camera images from VPLs instead
// (src/solver/VplTracer.h, src/output/InstantRenderer.h, src/cli/InstantSolve.cpp), so it has no Solver.
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
// InputError for a method not built yet, naming the issue that builds it (none today); cheap,
// so the solve command calls it before reading the scene.
void requireBuilt(Method m);
// The solver of method `m` over `state` with that method's settings (not Method::Instant).
std::unique_ptr<Solver> makeSolver(Method m, SolverState& state, const ProgressiveSettings& progressive,
                                   const StochasticSettings& stochastic);

}  // namespace hemirad
