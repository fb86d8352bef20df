#include "src/walk/ExperimentFlags.h"

#include "src/options/Options.h"

namespace hemirad {

std::vector<CLI::Option*> addExperimentFlags(CLI::App* x, ExperimentOptions& e) {
  using options::add;
  std::vector<CLI::Option*> flags{add(x, "--scenes", e.scenes),
                                  add(x, "--algorithms", e.algorithms),
                                  add(x, "--elements", e.elements),
                                  add(x, "--fps", e.walkthrough.fps),
                                  add(x, "--frame-ms", e.walkthrough.frameMs),
                                  add(x, "--camera-path", e.cameraPath, "SCENE.path beside each scene"),
                                  add(x, "--width", e.walkthrough.width),
                                  add(x, "--height", e.walkthrough.height),
                                  add(x, "--ambient", e.walkthrough.ambient),
                                  add(x, "--reference-convergence", e.referenceConvergence),
                                  add(x, "--fov-decay", e.progressive.fovDecayShots)};
  // --preset alone: the walkthroughs' item buffer and shooters (seed 004's runs: --preset seed003).
  flags.push_back(options::add(x, "--preset", e.progressive.preset)->each([&e](const std::string& name) {
    e.progressive.usePreset(name);
  }));
  flags.push_back(add(x, "--frame-shots", e.walkthrough.frameShots)->excludes(x->get_option("--frame-ms")));
  flags.push_back(add(x, "--backend", e.backend.kind));
  flags.push_back(add(x, "--gpu", e.backend.gpu));
  add(x, "--figure-size", e.figureSize);
  add(x, "--out-dir", e.out);  // a sweep SPEC's output folder too: not among those returned
  return flags;
}

}  // namespace hemirad
