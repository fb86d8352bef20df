// The Cornell box ready for camera renders without a solve: a coarse atlas whose elements all
// send the same light, per-pixel direct light, and the scene's own camera (DrawBands and MSAA).
#pragma once
#include <vector>

#include "src/output/DirectLight.h"
#include "src/scene/Atlas.h"
#include "src/scene/Camera.h"
#include "src/scene/Scene.h"
#include "src/solver/SolverState.h"

namespace hemirad::test {

struct CornellView {
  CornellView();
  Scene scene;
  Atlas atlas;
  SolverState state;
  std::vector<glm::vec4> sent;  // per element (0.05, 0.04, 0.03)
  DirectLight light;
  Camera camera;
};

}  // namespace hemirad::test
