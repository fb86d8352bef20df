// Loads an OBJ scene through the installed hemirad library and prints its polygon count:
// `polygons N`, as `hemirad info` prints it (tests/install/consumer.sh compares the two). Given
// OUT.glb too, it bakes the scene (a few shots on OSMesa) and exports its lightmap there, which
// links what a lightmap baker needs (the GL backend, the solver, the packer, the glTF writer).
#include <cstdio>

#include "gl/Backend.h"
#include "src/base/Error.h"
#include "src/output/GltfWriter.h"
#include "src/scene/Atlas.h"
#include "src/scene/Camera.h"
#include "src/scene/SceneLoader.h"
#include "src/solver/ProgressiveSolver.h"

namespace {
void bake(const hemirad::Scene& scene, const char* glb) {
  const auto backend = hemirad::gl::createBackend({});
  const hemirad::Atlas atlas = hemirad::buildAtlas(scene, hemirad::chooseTexelSize(scene, {.elements = 400}));
  hemirad::SolverState state(scene, atlas);
  hemirad::ProgressiveSettings settings;
  settings.stop.maxShots = 16;
  hemirad::ProgressiveSolver solver(state, settings);
  while (!solver.advance(16).done) {
  }
  const hemirad::Lightmap map = hemirad::writeGltf(hemirad::gltfPaths(glb), scene, atlas, state.readRadiosity(),
                                                   hemirad::resolveCamera(scene, std::nullopt), 1.0, 1.0);
  std::printf("lightmap     %d x %d, %zu elements\n", map.width, map.height, map.elements);
}
}  // namespace

int main(int argc, char** argv) {
  if (argc != 2 && argc != 3) {
    std::fprintf(stderr, "usage: consumer SCENE.obj [OUT.glb]\n");
    return 2;
  }
  try {
    const hemirad::Scene scene = hemirad::loadScene(argv[1]);
    std::printf("polygons     %zu\n", scene.polygons().size());
    if (argc == 3) bake(scene, argv[2]);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "consumer: %s\n", e.what());
    return 2;
  }
  return 0;
}
