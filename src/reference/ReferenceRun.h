// `reference`'s run (issue 31, docs/reference.md): the scene's camera view path-traced unbiased,
// with per-pixel standard errors from independent batches, written as files. Free of image
// libraries, so the lean hemirad-bench runs it on GPU machines too: the caller says how images
// become bytes (hemirad: OpenImageIO's EXR and PNG; hemirad-bench: PFM, src/output/Pfm.h).
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "gl/Backend.h"
#include "src/output/Image.h"
#include "src/reference/PathTracer.h"
#include "src/scene/SceneLoader.h"

namespace CLI {
class App;
}

namespace hemirad {

struct ReferenceOptions {
  std::string scene;
  LoadOptions load;
  ReferenceSettings settings;
  std::optional<std::string> camera;
  std::string out, standardError, image;  // --out (the mean), --stderr, --image (tone-mapped)
  double exposure = 0;
  gl::BackendOptions backend;
};

// The file formats of one binary: the extensions each output takes, and the encoders.
struct ReferenceWriters {
  std::vector<std::string> out, standardError, image;  // empty `image`: no --image flag
  std::function<std::string(const std::string& path, const Image&, double scale)> render;  // --out, --image
  std::function<std::string(const Image&)> linear;                                         // --stderr
};

// The flags, declared once for both binaries (--image and --exposure where `writers` has images).
void addReferenceFlags(CLI::App* command, ReferenceOptions& options, const ReferenceWriters& writers);
// Checks flags and outputs before any work, traces, writes every output or none; 0 on success.
int runReference(const ReferenceOptions& options, const ReferenceWriters& writers);

}  // namespace hemirad
