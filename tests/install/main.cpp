// Loads an OBJ scene through the installed hemirad library and prints its polygon count:
// `polygons N`, as `hemirad info` prints it (tests/install/consumer.sh compares the two).
#include <cstdio>

#include "src/base/Error.h"
#include "src/scene/SceneLoader.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: consumer SCENE.obj\n");
    return 2;
  }
  try {
    const hemirad::Scene scene = hemirad::loadScene(argv[1]);
    std::printf("polygons     %zu\n", scene.polygons().size());
  } catch (const hemirad::InputError& e) {
    std::fprintf(stderr, "consumer: %s\n", e.what());
    return 2;
  }
  return 0;
}
