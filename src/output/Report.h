// The report JSON (docs/design.md#report), plus what a reader needs to reproduce the run.
#pragma once
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "src/output/Smoothness.h"
#include "src/solver/Solver.h"
#include "src/solver/SolverState.h"

namespace hemirad {

struct RunInfo {
  std::string backend, renderer, method, algorithm, scene;  // method: `solve --method`
  // Progressive refinement: the item buffer's projection and the preset its plan started from,
  // with the flags that overrode it (src/solver/Presets.h); empty for the other methods.
  std::string projection, preset;
  double texelSize = 0;
  int itemSubdivision = 0, itemResolution = 0, shootLevel = 0, shootersPerPass = 0;
  // Progressive: camera images' direct light, "atlas" or "per-pixel" (empty: not the method's), and
  // per-pixel's cost: the emitters-only solve (src/solver/DirectSplit.h) and the camera render.
  std::string direct;
  std::string finalGather;  // with direct "per-pixel": "off" or "near"
  double directSplitMs = 0, directPixelsMs = 0;
  int supersample = 0, msaa = 0;  // the camera image's N x N cells and the samples a cell drawn (0: none)
  int gatherShares = 0;           // the draws its near gather took (Renderer::lastShares; 0: none)
  int directShares = 0;           // the draws its per-pixel direct light took (0: none)
  double refineNear = 0;          // progressive: receivers nearer than this many shooter sides see its parts
  std::string visibility;         // progressive: "item-buffer" or "bvh" (--visibility)
  unsigned importanceShots = 0;   // importance-driven solves
  unsigned deliveryShots = 0;     // perspective-driven solves: item buffers that delivered stored entries
  unsigned fovDecayShots = 0;     // ... and their decay interval
  std::size_t elements = 0, itemTriangles = 0;
  std::string discontinuities;    // "contact" or "off" (--discontinuities)
  std::size_t charts = 0;         // src/scene/Charts.h
  std::size_t clusters = 0;       // of them, clusters of small charts (src/scene/Clusters.h)
  std::size_t discShapes = 0;     // shooter-tree nodes past the shape budget, shot with the disc form factor
  std::size_t shooterBlocks = 0;  // progressive: the shooter blocks (ProgressiveSolver::shooterBlocks)
  int atlasWidth = 0, atlasHeight = 0;
  SolveStatus status;
  PassTimings timings;
  double totalMs = 0;
  std::uint64_t radiosityHash = 0;
  std::vector<ObjectRadiosity> objects;
  std::vector<float> convergenceHistory;
  // Issue 29's faceting and seam measures of what is shown (src/output/Smoothness.h), and the
  // seams' jump before stitching; absent where no report asks for them.
  std::optional<Smoothness> smoothness;
  double seamJumpUnstitched = 0;
};

nlohmann::json reportJson(const RunInfo& run);
// [{name, area, mean_radiosity: [r, g, b]}], the report's `objects` (docs/design.md#report).
nlohmann::json objectsJson(const std::vector<ObjectRadiosity>& objects);
void writeReport(const std::string& path, const RunInfo& run);

}  // namespace hemirad
