// `hemirad reference` and `hemirad compare` (issue 31, docs/reference.md): an unbiased path-traced
// image of a scene's camera view with its per-pixel standard error, and the error table of one
// image against another per region of that view.
#pragma once
#include <optional>
#include <string>

#include "gl/Backend.h"
#include "src/reference/PathTracer.h"
#include "src/scene/SceneLoader.h"

namespace hemirad {

struct ReferenceOptions {
  std::string scene;
  LoadOptions load;
  ReferenceSettings settings;
  std::optional<std::string> camera;
  std::string out, standardError, image;  // --out (mean, .exr or .png), --stderr (.exr), --image (.png)
  double exposure = 0;
  gl::BackendOptions backend;
};

struct CompareOptions {
  std::string a, b;   // A is judged against B (the reference)
  std::string scene;  // the scene and camera both images show: their regions
  LoadOptions load;
  std::optional<std::string> camera;
  std::string standardError;  // B's standard error (reference --stderr): the noise column
  std::string errorMap;       // PNG
  std::string markdownOut;    // --markdown
  double errorRange = 0.1;    // the error map's full colour
};

int runReference(const ReferenceOptions& options);
int runCompare(const CompareOptions& options);

}  // namespace hemirad
