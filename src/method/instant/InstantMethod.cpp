// --method instant: VPLs traced from the emitters, then the camera image shaded from them
// (seed 002). There is no atlas and no Solver: the images and the report are the outputs.
#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <cstring>
#include <nlohmann/json.hpp>

#include "src/base/AtomicFile.h"
#include "src/base/Clock.h"
#include "src/base/Error.h"
#include "src/base/Hash.h"
#include "src/cli/Solve.h"
#include "src/method/MethodFlag.h"
#include "src/output/ImageFile.h"
#include "src/output/InstantRenderer.h"
#include "src/output/Provenance.h"
#include "src/output/Supersample.h"
#include "src/scene/Camera.h"
#include "src/scene/SceneLoader.h"

namespace hemirad {

namespace {

// solve's instant radiosity: the seed and item mesh of the other methods' defaults (1, level 3).
InstantSettings instantSolveDefaults() {
  InstantSettings s;
  s.seed = 1;
  s.itemSubdivision = 3;
  return s;
}

struct InstantRun {
  InstantSettings settings = instantSolveDefaults();
  Shading shading = Shading::Deferred;
};

nlohmann::json instantReport(const SolveOptions& o, const InstantRun& i, const gl::RenderBackend& backend,
                             const VplTracer& tracer, const VplStats& stats, const InstantImage& render) {
  const VplLevels& levels = tracer.levels();
  return {{"method", "instant"},
          {"scene", o.scene},
          {"backend", backend.name()},
          {"renderer", backend.renderer()},
          {"seed", i.settings.seed},
          {"shading", shadingName(i.shading)},
          {"vpls", stats.vpls},
          {"paths", stats.paths},
          {"paths_per_level", std::vector<unsigned>(levels.count.begin(), levels.count.begin() + levels.deepest + 1)},
          {"rho_avg", tracer.rhoAvg()},
          {"shadow_resolution", i.settings.shadowResolution},
          {"clamp", i.settings.clamp},
          {"clamp_bias", render.clampBias()},
          {"emitted_power", stats.emitted},
          {"escaped_power", stats.escaped},
          {"escaped_fraction", stats.emitted > 0 ? stats.escaped / stats.emitted : 0.0},
          {"escaped_paths", stats.escapedPaths},
          {"behind_power", stats.behind},
          {"behind_paths", stats.behindPaths},
          {"image", {o.width, o.height}},
          {"supersample", o.supersample},
          {"image_mean_luminance", meanLuminance(render.image)},
          {"image_hash", fmt::format("{:016x}", imageHash(render.image))}};
}

class InstantMethod final : public MethodUnit {
 public:
  std::string name() const override { return "instant"; }
  std::vector<MethodFlag> flags() override {
    InstantSettings& i = run_.settings;
    return {bindFlag("--item-subdiv", i.itemSubdivision),
            bindFlag("--seed", i.seed),
            bindFlag("--vpls", i.vpls),
            bindFlag("--vpl-bounces", i.bounces),
            bindFlag("--vpl-clamp", i.clamp),
            bindFlag("--shadow-res", i.shadowResolution),
            parseFlag(
                "--shading", run_.shading,
                [](const std::string& s) { return s == "forward" ? Shading::Forward : Shading::Deferred; }, "deferred"),
            bindFlag("--interleave", i.interleave)};
  }
  // Solve's outputs of radiosity per element, and checkpoints, mean nothing here.
  void settle(const SolveOptions& o) override {
    if (!o.atlas.empty() || !o.ply.empty() || !o.gltf.empty())
      throw InputError(
          "--atlas, --ply and --gltf need radiosity per element; --method instant shades camera pixels "
          "only (--out, --image)");
    if (!o.checkpoint.empty() || !o.resume.empty()) throw InputError("--method instant has nothing to checkpoint");
    if (o.msaa.value_or(1) > 1)
      throw InputError("--msaa: --method instant shades every sample of its G-buffer (use --supersample)");
    // Its deferred passes rebuild each sample's ray from the pixel grid: no shifted draws.
    if (o.supersample > SupersampleGrid::kMaxScale)
      throw InputError(fmt::format("--supersample {}: --method instant samples at most {} a pixel side", o.supersample,
                                   SupersampleGrid::kMaxScale));
  }
  int solve(const SolveOptions& o) const override;
  bool checkpoints() const override { return false; }
  std::string quickFlags() const override { return "--vpls 64 --shadow-res 32 --width 48 --height 32"; }
  // Emission and one bounce per VPL level 0..15: E (1 + rho + ... + rho^16); unclamped, so only
  // the VPL sampling's noise remains (tests/InstantGLTest.cpp measures its standard error).
  ClosedBoxRun closedBox() const override {
    return {"--vpls 512 --vpl-bounces 15 --vpl-clamp 0 --shadow-res 64 --width 48 --height 32",
            2 * (1 - std::pow(0.5, 17)), 0.03};
  }

 private:
  InstantRun run_;
};

int InstantMethod::solve(const SolveOptions& o) const {
  const auto start = Clock::now();
  checkSolveOutputs(o, {{"the scene", o.scene}});
  Scene scene = loadScene(o.scene, o.load);
  printWarnings(scene.warnings);
  checkSolveOutputs(o, scene.sources);
  validateSolvable(scene);
  const Camera camera = resolveCamera(scene, o.camera);
  auto backend = gl::createBackend(o.backend);
  if (o.backend.kind == gl::BackendKind::Auto)
    fmt::print(stderr, "hemirad: backend auto chose {} ({})\n", backend->name(), backend->renderer());

  VplTracer tracer(scene, run_.settings);
  const VplStats stats = tracer.trace();
  InstantRenderer renderer(scene, tracer, run_.settings);
  const InstantImage render = renderer.render(camera, o.width, o.height, o.supersample, run_.shading);
  const double scale = exposureScale(render.image, o.exposure);
  OutputBatch outputs;  // all or none
  if (!o.out.empty()) outputs.add("--out", o.out, encodeRender(o.out, render.image, scale));
  if (!o.image.empty()) outputs.add("--image", o.image, encodePng(render.image, scale));
  nlohmann::json report = instantReport(o, run_, *backend, tracer, stats, render);
  report["total_ms"] = msSince(start);
  report["provenance"] = provenanceJson(provenance(backend->name(), backend->renderer()));
  if (!o.report.empty()) outputs.add("--report", o.report, report.dump(2) + "\n");
  outputs.commit();
  fmt::print(stderr,
             "hemirad: {}: {} VPLs from {} paths, {:.2f} % of the power escaped, clamp bias {:.2f} %, {} "
             "shading in {:.0f} ms ({}, {})\n",
             o.scene, stats.vpls, stats.paths, 100.0 * report["escaped_fraction"].get<double>(),
             100.0 * render.clampBias(), shadingName(run_.shading), msSince(start), backend->name(),
             backend->renderer());
  return 0;
}

}  // namespace

std::uint64_t imageHash(const Image& image) {
  Fnv1a h;
  h.add(image.rgb.data(), image.rgb.size() * sizeof(float));
  return h.value();
}

std::unique_ptr<MethodUnit> makeInstantMethod() { return std::make_unique<InstantMethod>(); }

}  // namespace hemirad
