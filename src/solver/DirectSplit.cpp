#include "src/solver/DirectSplit.h"

#include "src/solver/SolverState.h"

namespace hemirad {

std::vector<glm::vec4> directOnlyRadiosity(const Scene& scene, const Atlas& atlas, ProgressiveSettings settings,
                                           const Camera& camera, double aspect) {
  settings.directOnly = true;
  settings.refineNear = settings.nearRefinement();  // the full solve's, which the stop rule below no longer gives
  // No target: select.comp stops once nothing is unshot, i.e. once every emitter has shot.
  settings.stop.targetConvergence = 0;
  settings.timings = gl::TimerMode::Off;
  SolverState state(scene, atlas);
  ProgressiveSolver solver(state, settings);
  if (settings.importanceDriven()) solver.look(camera, aspect);
  advanceToStop(solver, SolveStatus{});
  return state.readRadiosity();
}

std::vector<glm::vec4> indirectPart(const std::vector<glm::vec4>& B, const std::vector<glm::vec4>& direct) {
  std::vector<glm::vec4> indirect(B.size());
  for (std::size_t t = 0; t < B.size(); ++t) indirect[t] = glm::vec4(glm::vec3(B[t]) - glm::vec3(direct[t]), B[t].w);
  return indirect;
}

}  // namespace hemirad
