#include "src/reference/ReferenceRun.h"

#include <fmt/format.h>
#include <unistd.h>

#include <chrono>

#include "src/base/AtomicFile.h"
#include "src/base/DataDir.h"
#include "src/base/OutputPaths.h"
#include "src/options/Options.h"
#include "src/reference/BatchStatistics.h"
#include "src/scene/Camera.h"

namespace hemirad {

namespace {

std::vector<OutputPath> referenceOutputs(const ReferenceOptions& o, const ReferenceWriters& w) {
  std::vector<OutputPath> outputs{{"--out", o.out, w.out}};
  if (!o.standardError.empty()) outputs.push_back({"--stderr", o.standardError, w.standardError});
  if (!o.image.empty()) outputs.push_back({"--image", o.image, w.image});
  return outputs;
}

ReferenceEstimate trace(const Scene& scene, const Camera& camera, const ReferenceSettings& s) {
  PathTracer tracer(scene);
  BatchStatistics statistics(s.width, s.height, s.samples / s.batches);
  const bool terminal = isatty(STDERR_FILENO);  // a batch counter for long runs, never in logs
  tracer.render(camera, s, [&](const std::vector<glm::vec4>& sums) {
    statistics.add(sums);
    if (terminal) fmt::print(stderr, "\rhemirad: reference: batch {} of {}", statistics.batches(), s.batches);
  });
  if (terminal) fmt::print(stderr, "\n");
  return statistics.estimate();
}

}  // namespace

void addReferenceFlags(CLI::App* r, ReferenceOptions& o, const ReferenceWriters& w) {
  using options::add;
  r->add_option("scene", o.scene, "Wavefront OBJ (materials from its MTL) or glTF 2.0 (.gltf, .glb)")
      ->required()
      ->type_name("SCENE")
      ->transform(
          CLI::Validator([](std::string& path) { return path = findScene(path), std::string(); }, "", "shipped"))
      ->check(CLI::ExistingFile);
  add(r, "--emission", o.load.emission);
  add(r, "--spp", o.settings.samples);
  add(r, "--batches", o.settings.batches);
  add(r, "--bounces", o.settings.bounces);
  add(r, "--seed", o.settings.seed);
  add(r, "--camera", o.camera);
  add(r, "--width", o.settings.width);
  add(r, "--height", o.settings.height);
  add(r, "--out", o.out)->required();
  add(r, "--stderr", o.standardError);
  if (!w.image.empty()) add(r, "--image", o.image), add(r, "--exposure", o.exposure);
  add(r, "--backend", o.backend.kind);
  add(r, "--gpu", o.backend.gpu);
}

int runReference(const ReferenceOptions& o, const ReferenceWriters& w) {
  checkReferenceSettings(o.settings);  // bad flags fail before the scene is read
  checkOutputs(referenceOutputs(o, w), {{"the scene", o.scene}});
  const Scene scene = loadScene(o.scene, o.load);
  validateSolvable(scene);
  checkOutputs(referenceOutputs(o, w), scene.sources);
  const Camera camera = resolveCamera(scene, o.camera);
  auto backend = gl::createBackend(o.backend);
  const auto t0 = std::chrono::steady_clock::now();
  const ReferenceSettings& s = o.settings;
  const ReferenceEstimate e = trace(scene, camera, s);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  OutputBatch outputs;
  const double scale = exposureScale(e.mean, o.exposure);
  outputs.add("--out", o.out, w.render(o.out, e.mean, scale));
  if (!o.standardError.empty()) outputs.add("--stderr", o.standardError, w.linear(e.standardError));
  if (!o.image.empty()) outputs.add("--image", o.image, w.render(o.image, e.mean, scale));
  outputs.commit();
  const std::string capped = s.bounces < kReferenceBounceCap ? fmt::format(", at most {} bounces", s.bounces) : "";
  fmt::print(
      stderr,
      "hemirad: reference: {} x {} px, {} paths per pixel ({} batches of {}, seed {}{}) in {:.2f} s on {}; mean B "
      "{:.6g}, mean standard error {:.4g} ({:.3f} % of it)\n",
      s.width, s.height, s.samples, s.batches, s.samples / s.batches, s.seed, capped, seconds, backend->renderer(),
      e.meanLuminance, e.meanStandardError, e.meanLuminance > 0 ? 100 * e.meanStandardError / e.meanLuminance : 0.0);
  return 0;
}

}  // namespace hemirad
