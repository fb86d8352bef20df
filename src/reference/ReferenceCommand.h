// `hemirad reference`'s image formats and `hemirad compare` (issue 31, docs/reference.md): the
// error table of one image against another (an unbiased reference: src/reference/ReferenceRun.h)
// per region of the scene's camera view.
#pragma once
#include <optional>
#include <string>

#include "gl/Backend.h"
#include "src/reference/ReferenceRun.h"
#include "src/scene/SceneLoader.h"

namespace hemirad {

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

// hemirad's image formats for `reference`: EXR or PNG (--out), EXR (--stderr), PNG (--image).
ReferenceWriters imageFileWriters();
int runCompare(const CompareOptions& options);

}  // namespace hemirad
