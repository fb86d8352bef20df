// `hemirad solve --method instant`: VPLs traced from the emitters, then the camera image shaded
// from them (seed 002). There is no atlas: the images and the report are the outputs.
#include <fmt/format.h>

#include <chrono>
#include <cstring>
#include <nlohmann/json.hpp>

#include "src/base/AtomicFile.h"
#include "src/base/Clock.h"
#include "src/base/Error.h"
#include "src/base/Hash.h"
#include "src/cli/Solve.h"
#include "src/output/ImageFile.h"
#include "src/output/Provenance.h"
#include "src/scene/Camera.h"
#include "src/scene/SceneLoader.h"

namespace hemirad {

namespace {

// Everything checkable before the scene is read.
void checkInstantInputs(const SolveOptions& o) {
  if (!o.atlas.empty() || !o.ply.empty() || !o.gltf.empty())
    throw InputError("--atlas, --ply and --gltf need radiosity per element; --method instant shades camera pixels only "
                     "(--out, --image)");
  if (!o.checkpoint.empty() || !o.resume.empty()) throw InputError("--method instant has nothing to checkpoint");
  if (!o.cameraPath.empty()) throw InputError("--camera-path is for --method progressive, not instant");
  checkSolveOutputs(o, {{"the scene", o.scene}});
}

nlohmann::json instantReport(const SolveOptions& o, const gl::RenderBackend& backend, const VplTracer& tracer,
                             const VplStats& stats, const InstantImage& render) {
  const VplLevels& levels = tracer.levels();
  return {{"method", "instant"}, {"scene", o.scene}, {"backend", backend.name()}, {"renderer", backend.renderer()},
          {"seed", o.instant.seed}, {"shading", shadingName(o.shading)},
          {"vpls", stats.vpls}, {"paths", stats.paths},
          {"paths_per_level", std::vector<unsigned>(levels.count.begin(), levels.count.begin() + levels.deepest + 1)},
          {"rho_avg", tracer.rhoAvg()}, {"shadow_resolution", o.instant.shadowResolution},
          {"clamp", o.instant.clamp}, {"clamp_bias", render.clampBias()},
          {"emitted_power", stats.emitted}, {"escaped_power", stats.escaped},
          {"escaped_fraction", stats.emitted > 0 ? stats.escaped / stats.emitted : 0.0},
          {"escaped_paths", stats.escapedPaths}, {"behind_power", stats.behind}, {"behind_paths", stats.behindPaths},
          {"image", {o.width, o.height}}, {"supersample", o.supersample},
          {"image_mean_luminance", meanLuminance(render.image)},
          {"image_hash", fmt::format("{:016x}", imageHash(render.image))}};
}

}  // namespace

std::uint64_t imageHash(const Image& image) {
  Fnv1a h;
  h.add(image.rgb.data(), image.rgb.size() * sizeof(float));
  return h.value();
}

int runInstantSolve(const SolveOptions& o) {
  const auto start = Clock::now();
  checkInstantInputs(o);
  Scene scene = loadScene(o.scene, o.load);
  printWarnings(scene.warnings);
  checkSolveOutputs(o, scene.sources);
  validateSolvable(scene);
  const Camera camera = resolveCamera(scene, o.camera);
  auto backend = gl::createBackend(o.backend);
  if (o.backend.kind == gl::BackendKind::Auto)
    fmt::print(stderr, "hemirad: backend auto chose {} ({})\n", backend->name(), backend->renderer());

  VplTracer tracer(scene, o.instant);
  const VplStats stats = tracer.trace();
  InstantRenderer renderer(scene, tracer, o.instant);
  const InstantImage render = renderer.render(camera, o.width, o.height, o.supersample, o.shading);
  const double scale = exposureScale(render.image, o.exposure);
  OutputBatch outputs;  // all or none
  if (!o.out.empty()) outputs.add("--out", o.out, encodeRender(o.out, render.image, scale));
  if (!o.image.empty()) outputs.add("--image", o.image, encodePng(render.image, scale));
  nlohmann::json report = instantReport(o, *backend, tracer, stats, render);
  report["total_ms"] = msSince(start);
  report["provenance"] = provenanceJson(provenance(backend->name(), backend->renderer()));
  if (!o.report.empty()) outputs.add("--report", o.report, report.dump(2) + "\n");
  outputs.commit();
  fmt::print(stderr, "hemirad: {}: {} VPLs from {} paths, {:.2f} % of the power escaped, clamp bias {:.2f} %, {} "
             "shading in {:.0f} ms ({}, {})\n", o.scene, stats.vpls, stats.paths,
             100.0 * report["escaped_fraction"].get<double>(), 100.0 * render.clampBias(), shadingName(o.shading),
             msSince(start), backend->name(), backend->renderer());
  return 0;
}

}  // namespace hemirad
