#include "src/reference/ReferenceCommand.h"

#include <fmt/format.h>

#include <chrono>
#include <filesystem>

#include <unistd.h>

#include "src/base/AtomicFile.h"
#include "src/base/Error.h"
#include "src/base/OutputPaths.h"
#include "src/output/ImageFile.h"
#include "src/reference/BatchStatistics.h"
#include "src/reference/ErrorTable.h"
#include "src/reference/PixelRegions.h"
#include "src/scene/Camera.h"

namespace hemirad {

namespace {

std::vector<OutputPath> referenceOutputs(const ReferenceOptions& o) {
  std::vector<OutputPath> outputs{{"--out", o.out, {".exr", ".png"}}};
  if (!o.standardError.empty()) outputs.push_back({"--stderr", o.standardError, {".exr"}});
  if (!o.image.empty()) outputs.push_back({"--image", o.image, {".png"}});
  return outputs;
}

Image readSized(const std::string& path, const std::string& what, int width, int height) {
  Image image = readImage(path);
  if (width && (image.width != width || image.height != height))
    throw InputError(fmt::format("{} ({}) is {} x {} pixels, the images compared {} x {}", what, path, image.width,
                                 image.height, width, height));
  return image;
}

}  // namespace

int runReference(const ReferenceOptions& o) {
  checkReferenceSettings(o.settings);  // bad flags fail before the scene is read
  checkOutputs(referenceOutputs(o), {{"the scene", o.scene}});
  const Scene scene = loadScene(o.scene, o.load);
  validateSolvable(scene);
  checkOutputs(referenceOutputs(o), scene.sources);
  const Camera camera = resolveCamera(scene, o.camera);
  auto backend = gl::createBackend(o.backend);
  const auto t0 = std::chrono::steady_clock::now();
  PathTracer tracer(scene);
  const ReferenceSettings& s = o.settings;
  BatchStatistics statistics(s.width, s.height, s.samples / s.batches);
  const bool terminal = isatty(STDERR_FILENO);  // a batch counter for long runs, never in logs
  tracer.render(camera, s, [&](const std::vector<glm::vec4>& sums) {
    statistics.add(sums);
    if (terminal) fmt::print(stderr, "\rhemirad: reference: batch {} of {}", statistics.batches(), s.batches);
  });
  if (terminal) fmt::print(stderr, "\n");
  const ReferenceEstimate e = statistics.estimate();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  OutputBatch outputs;
  const double scale = exposureScale(e.mean, o.exposure);
  outputs.add("--out", o.out, encodeRender(o.out, e.mean, scale));
  if (!o.standardError.empty()) outputs.add("--stderr", o.standardError, encodeExr(e.standardError));
  if (!o.image.empty()) outputs.add("--image", o.image, encodePng(e.mean, scale));
  outputs.commit();
  fmt::print(stderr,
             "hemirad: reference: {} x {} px, {} paths per pixel ({} batches of {}, seed {}) in {:.2f} s on {}; mean B "
             "{:.6g}, mean standard error {:.4g} ({:.3f} % of it)\n",
             s.width, s.height, s.samples, s.batches, s.samples / s.batches, s.seed, seconds, backend->renderer(),
             e.meanLuminance, e.meanStandardError,
             e.meanLuminance > 0 ? 100 * e.meanStandardError / e.meanLuminance : 0.0);
  return 0;
}

int runCompare(const CompareOptions& o) {
  for (const std::string& path : {o.a, o.b, o.standardError})  // a PNG holds tone-mapped, not linear, light
    if (!path.empty() && std::filesystem::path(path).extension() != ".exr")
      throw InputError(path + ": compare reads linear EXR images (solve --out X.exr, reference --out X.exr)");
  std::vector<OutputPath> outputs;
  if (!o.errorMap.empty()) outputs.push_back({"--error-map", o.errorMap, {".png"}});
  if (!o.markdownOut.empty()) outputs.push_back({"--markdown", o.markdownOut, {".md"}, true});
  std::vector<InputPath> inputs{{"image A", o.a}, {"image B", o.b}, {"the scene", o.scene}};
  if (!o.standardError.empty()) inputs.push_back({"B's standard error (--stderr)", o.standardError});
  checkOutputs(outputs, inputs);
  const Image a = readImage(o.a);
  const Image b = readSized(o.b, "image B", a.width, a.height);
  const Image se = o.standardError.empty() ? Image{} : readSized(o.standardError, "--stderr", a.width, a.height);
  const Scene scene = loadScene(o.scene, o.load);
  const PixelRegions regions = pixelRegions(scene, resolveCamera(scene, o.camera), a.width, a.height);
  const std::string table = markdown(errorTable(scene, regions, a, b, se));
  OutputBatch files;
  if (!o.errorMap.empty()) files.add("--error-map", o.errorMap, encodePng(errorMap(regions, a, b, o.errorRange), 1.0));
  if (!o.markdownOut.empty()) files.add("--markdown", o.markdownOut, table);
  files.commit();
  if (o.markdownOut != "-") fmt::print("{}", table);  // `--markdown -` has printed it already
  return 0;
}

}  // namespace hemirad
