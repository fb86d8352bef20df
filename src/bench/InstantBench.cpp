#include "src/bench/InstantBench.h"

#include <fmt/format.h>

#include <chrono>
#include <map>

#include "src/base/Clock.h"
#include "src/output/InstantRenderer.h"
#include "src/scene/Camera.h"
#include "src/scene/SceneLoader.h"

namespace hemirad {

namespace {

// Seed 002, Figure 5: fps on a GeForce GTX Titan (forward, deferred), its scene at its size.
// Its frames: VPLs traced once after loading, then every frame shades every VPL (our shading-only
// frame; the seed does not say a shadow map per VPL is rendered each frame).
const std::map<unsigned, std::pair<double, double>> kSeedFigure5{
    {128, {252.75, 280.88}}, {192, {176.94, 216.57}}, {256, {135.73, 186.81}}, {320, {108.24, 160.84}},
    {384, {92.91, 141.29}},  {448, {80.76, 131.34}},  {512, {68.73, 120.28}}};

// Frames per second over `frames` frames after one untimed (shaders compile at first use). A full
// frame traces the VPLs again and renders their shadow maps; a shading-only frame is a camera
// move (the eye steps back and forth by 1e-4 of the scene, so no frame repeats the last).
double fps(gl::RenderBackend& backend, VplTracer& tracer, InstantRenderer& renderer, const Camera& camera,
           const BenchOptions& o, Shading shading, bool full) {
  Camera moved = camera;
  moved.eye += 1e-4 * tracer.sceneDiagonal() * glm::normalize(camera.eye - camera.target);
  auto frame = [&](unsigned f) {
    if (full) tracer.dispatch(), renderer.vplsChanged();
    renderer.draw(f % 2 ? moved : camera, o.width, o.height, shading);
  };
  frame(0);
  backend.finish();
  const auto t0 = Clock::now();
  for (unsigned f = 0; f < o.iterations; ++f) frame(f + 1);
  backend.finish();
  return o.iterations / std::chrono::duration<double>(Clock::now() - t0).count();
}

std::string seedCell(unsigned vpls, bool deferred) {
  auto it = kSeedFigure5.find(vpls);
  if (it == kSeedFigure5.end()) return "n/a";
  return fmt::format("{:.2f}", deferred ? it->second.second : it->second.first);
}

}  // namespace

nlohmann::json benchInstant(gl::RenderBackend& backend, const BenchOptions& o,
                            const std::function<void(const std::string&)>& say) {
  say(
      fmt::format("{} frames timed per row at {} x {}, {}^2 shadow maps. Full frame: trace + every VPL's shadow map "
                  "+ shading; shading only: a camera move (G-buffer, shading, interleaving filter), the shadow maps "
                  "kept. Seed 002 traced once after loading and timed shading frames: compare its columns with "
                  "shading only.\n\n",
                  o.iterations, o.width, o.height, o.instant.shadowResolution));
  say("| scene | VPLs | interleave | paths | trace ms | full frame forward fps | full frame deferred fps | shading "
      "only forward fps | shading only deferred fps | seed 002 forward fps (GTX Titan) | seed 002 deferred fps (GTX "
      "Titan) |\n|---|---|---|---|---|---|---|---|---|---|---|\n");
  nlohmann::json rows = nlohmann::json::array();
  for (const auto& path : o.scenes) {
    Scene scene = loadScene(path);
    validateSolvable(scene);
    const Camera camera = resolveCamera(scene, std::nullopt);
    for (unsigned vpls : o.vpls)
      for (int interleave : o.interleave) {
        InstantSettings settings = o.instant;
        settings.vpls = vpls;
        settings.interleave = interleave;
        VplTracer tracer(scene, settings);
        tracer.trace();  // untimed: compiles the shader
        backend.finish();
        const auto t0 = Clock::now();
        const VplStats stats = tracer.trace();
        const double traceMs = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
        InstantRenderer renderer(scene, tracer, settings);
        double f[2][2];  // [full][deferred]
        for (int full = 1; full >= 0; --full)
          for (int deferred = 0; deferred < 2; ++deferred)
            f[full][deferred] =
                fps(backend, tracer, renderer, camera, o, deferred ? Shading::Deferred : Shading::Forward, full);
        say(fmt::format("| {} | {} | {} | {} | {:.2f} | {:.2f} | {:.2f} | {:.2f} | {:.2f} | {} | {} |\n", path, vpls,
                        interleave, stats.paths, traceMs, f[1][0], f[1][1], f[0][0], f[0][1], seedCell(vpls, false),
                        seedCell(vpls, true)));
        nlohmann::json row = {{"scene", path},
                              {"vpls", vpls},
                              {"interleave", interleave},
                              {"paths", stats.paths},
                              {"trace_ms", traceMs},
                              {"full_frame_fps", {{"forward", f[1][0]}, {"deferred", f[1][1]}}},
                              {"shading_only_fps", {{"forward", f[0][0]}, {"deferred", f[0][1]}}}};
        if (auto it = kSeedFigure5.find(vpls); it != kSeedFigure5.end())
          row["seed_002_gtx_titan_fps"] = {{"forward", it->second.first}, {"deferred", it->second.second}};
        rows.push_back(row);
      }
  }
  return rows;
}

}  // namespace hemirad
