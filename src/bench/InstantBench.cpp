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
const std::map<unsigned, std::pair<double, double>> kSeedFigure5{
    {128, {252.75, 280.88}}, {192, {176.94, 216.57}}, {256, {135.73, 186.81}}, {320, {108.24, 160.84}},
    {384, {92.91, 141.29}},  {448, {80.76, 131.34}},  {512, {68.73, 120.28}}};

// Frames per second over `frames` frames after one untimed (shaders compile at first use).
double fps(gl::RenderBackend& backend, InstantRenderer& renderer, const Camera& camera, const BenchOptions& o,
           Shading shading) {
  renderer.draw(camera, o.width, o.height, shading);
  backend.finish();
  const auto t0 = Clock::now();
  for (unsigned f = 0; f < o.iterations; ++f) renderer.draw(camera, o.width, o.height, shading);
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
  say(fmt::format("{} frames timed per row at {} x {}; a frame: shadow maps of every VPL ({}^2), then shading\n\n",
                  o.iterations, o.width, o.height, o.instant.shadowResolution));
  say("| scene | VPLs | paths | trace ms | forward fps | deferred fps | seed 002 forward fps (GTX Titan) | seed 002 "
      "deferred fps (GTX Titan) |\n|---|---|---|---|---|---|---|---|\n");
  nlohmann::json rows = nlohmann::json::array();
  for (const auto& path : o.scenes) {
    Scene scene = loadScene(path);
    validateSolvable(scene);
    const Camera camera = resolveCamera(scene, std::nullopt);
    for (unsigned vpls : o.vpls) {
      InstantSettings settings = o.instant;
      settings.vpls = vpls;
      VplTracer tracer(scene, settings);
      tracer.trace();  // untimed: compiles the shader
      backend.finish();
      const auto t0 = Clock::now();
      const VplStats stats = tracer.trace();
      const double traceMs = std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
      InstantRenderer renderer(scene, tracer, settings);
      const double forward = fps(backend, renderer, camera, o, Shading::Forward);
      const double deferred = fps(backend, renderer, camera, o, Shading::Deferred);
      say(fmt::format("| {} | {} | {} | {:.2f} | {:.2f} | {:.2f} | {} | {} |\n", path, vpls, stats.paths, traceMs, forward,
                      deferred, seedCell(vpls, false), seedCell(vpls, true)));
      nlohmann::json row = {{"scene", path}, {"vpls", vpls}, {"paths", stats.paths}, {"trace_ms", traceMs},
                            {"forward_fps", forward}, {"deferred_fps", deferred}};
      if (auto it = kSeedFigure5.find(vpls); it != kSeedFigure5.end())
        row["seed_002_gtx_titan_fps"] = {{"forward", it->second.first}, {"deferred", it->second.second}};
      rows.push_back(row);
    }
  }
  return rows;
}

}  // namespace hemirad
