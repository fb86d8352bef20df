#include "tests/support/CornellView.h"

#include "src/scene/SceneLoader.h"
#include "tests/support/Support.h"

namespace hemirad::test {

CornellView::CornellView()
    : scene(loadScene(sourcePath("scenes/cornell/cornell.obj"))),
      atlas(buildAtlas(scene, 60.0)),
      state(scene, atlas),
      sent(atlas.polygonOf.size(), glm::vec4(0.05f, 0.04f, 0.03f, 0.0f)),
      light(scene, state.farDistance),
      camera(resolveCamera(scene, "")) {}

}  // namespace hemirad::test
