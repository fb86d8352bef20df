#include "src/output/Report.h"

#include <fmt/format.h>

#include "src/base/AtomicFile.h"
#include "src/base/Error.h"
#include "src/output/Provenance.h"

namespace hemirad {

nlohmann::json objectsJson(const std::vector<ObjectRadiosity>& objects) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& o : objects)
    out.push_back({{"name", o.name}, {"area", o.area}, {"mean_radiosity", {o.mean.x, o.mean.y, o.mean.z}}});
  return out;
}

// One [shots, convergence] entry where a pass began (the GPU writes the convergence at a pass's
// start for each of its shots: select.comp), and the last, after every shot: 60 KB of repeats per
// Cornell solve become a few hundred bytes.
nlohmann::json historyJson(const std::vector<float>& h) {
  nlohmann::json out = nlohmann::json::array();
  auto same = [](float a, float b) { return a == b || (a != a && b != b); };  // NaN: stochastic, none
  for (std::size_t i = 0; i < h.size(); ++i)
    if (i == 0 || i + 1 == h.size() || !same(h[i - 1], h[i])) out.push_back({i, h[i]});
  return out;
}

nlohmann::json reportJson(const RunInfo& r) {
  using nlohmann::json;
  json report = {
      {"backend", r.backend},
      {"renderer", r.renderer},
      {"method", r.method},
      {"algorithm", r.algorithm},
      {"scene", r.scene},
      {"elements", r.elements},
      {"charts", r.charts},
      {"clusters", r.clusters},
      {"disc_shapes", r.discShapes},
      {"texel_size", r.texelSize},
      {"atlas", {{"width", r.atlasWidth}, {"height", r.atlasHeight}}},
      {"shots", r.status.shots},
      {"convergence", r.status.convergence},
      {"item_subdivision", r.itemSubdivision},
      {"item_resolution", r.itemResolution},
      {"item_triangles", r.itemTriangles},
      {"shoot_level", r.shootLevel},
      {"refine_near", r.refineNear},
      {"shooters_per_pass", r.shootersPerPass},
      {"importance_shots", r.importanceShots},
      {"delivery_shots", r.deliveryShots},
      {"fov_decay_shots", r.fovDecayShots},
      {"timings_ms",
       {{"total", r.totalMs},
        {"item_buffer", r.timings.itemBuffer},
        {"gather", r.timings.gather},
        {"select", r.timings.select},
        {"readback", r.timings.readback}}},
      {"radiosity_hash", fmt::format("{:016x}", r.radiosityHash)},
      {"convergence_history", historyJson(r.convergenceHistory)},
      {"objects", objectsJson(r.objects)},
      {"provenance", provenanceJson(provenance(r.backend, r.renderer))},
  };
  if (!r.preset.empty()) report["preset"] = r.preset;
  if (!r.projection.empty()) report["projection"] = r.projection;
  if (!r.direct.empty()) report["direct"] = r.direct;
  if (!r.discontinuities.empty()) report["discontinuities"] = r.discontinuities;
  if (!r.visibility.empty()) report["visibility"] = r.visibility;
  if (r.shooterBlocks > 0) report["shooter_blocks"] = r.shooterBlocks;
  if (r.direct == "per-pixel") report["final_gather"] = r.finalGather;
  if (r.supersample) report["camera_image"] = {{"supersample", r.supersample}, {"msaa", r.msaa}};
  if (r.gatherShares) report["camera_image"]["gather_shares"] = r.gatherShares;
  if (r.directShares) report["camera_image"]["direct_shares"] = r.directShares;
  if (const std::optional<Smoothness>& m = r.smoothness)
    report["smoothness"] = {{"facet_edges", m->facetEdges},
                            {"facet_jump", m->facetJump},
                            {"seams", m->seams},
                            {"seam_jump", m->seamJump},
                            {"seam_jump_unstitched", r.seamJumpUnstitched},
                            {"inside_jump", m->insideJump}};
  if (r.direct == "per-pixel")
    report["direct_ms"] = {
        {"total", r.directSplitMs + r.directPixelsMs}, {"split", r.directSplitMs}, {"pixels", r.directPixelsMs}};
  return report;
}

void writeReport(const std::string& path, const RunInfo& run) { writeTextFile(path, reportJson(run).dump(2) + "\n"); }

}  // namespace hemirad
