// Instant radiosity's light paths (seed 002 §3, Keller 1997): virtual point lights traced in a
// compute shader (shaders/vpl_trace.comp) through the scene's BVH, kept on the GPU for the
// shadow maps and the shading (src/output/InstantRenderer.h). The SSBO structs are whole vec4s
// (seed 002 §4.1: drivers pad anything smaller differently); tests read them back on each backend.
#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "gl/Objects.h"
#include "src/scene/Scene.h"
#include "src/solver/Bvh.h"
#include "src/solver/BvhBuffers.h"

namespace hemirad {

inline constexpr int kMaxVplLevels = 16;  // MAX_LEVELS in vpl_trace.comp: bounces 0 to 15

// One VPL as vpl.glsl lays it out (std430).
struct GpuVpl {
  glm::vec4 position;  // w: polygon id (uint bits)
  glm::vec4 normal;    // w: bounce level
  glm::vec4 flux;      // rgb power; 0: an empty slot (its path escaped earlier)
};
static_assert(sizeof(GpuVpl) == 48);

// The per-polygon table of shaders/scene.glsl (std430): plane, reflectance, emission, vertex range.
struct GpuPolygon {
  glm::vec4 plane, reflectance, emission;
  glm::uvec4 vertices;
};
static_assert(sizeof(GpuPolygon) == 64);
// The table for every polygon of `scene` (chart 0: the tracers read no atlas), its vertices in `vertices`.
std::vector<GpuPolygon> gpuPolygonTable(const Scene& scene, std::vector<glm::vec4>& vertices);

struct InstantSettings {
  unsigned vpls = 256;  // VPL slots: exactly this many, over all levels
  int bounces = 8;      // the deepest level: VPLs at 0 (on emitters) to `bounces` hits
  unsigned seed = 0;
  int shadowResolution = 128;  // each VPL's hemispherical shadow map, pixels a side
  int itemSubdivision = 2;     // the shadow maps' mesh: 1-to-4 splits (curved projection)
  double clamp = 0.05;         // cos cos / r^2 is clamped at 1 / (clamp x scene diagonal)^2
  int interleave = 1;          // n: each pixel of an n x n tile shades with 1 / n^2 of the VPLs (1: all)
};

// Keller's quasi-random walk: n[j] paths reach level j, n[j] ~ rhoAvg^j n[0], sum n[j] = vpls.
struct VplLevels {
  std::array<unsigned, kMaxVplLevels> count{}, offset{};
  int deepest = 0;  // the last level with paths
};
VplLevels planLevels(unsigned vpls, double rhoAvg, int bounces);

// Power bookkeeping of one trace (luminance, W or the scene's unit): emitted = what the paths
// carry from the emitters; escaped = what left an open scene; behind = what met a polygon's
// back (black) side.
struct VplStats {
  unsigned vpls = 0, paths = 0, escapedPaths = 0, behindPaths = 0;
  double emitted = 0, escaped = 0, behind = 0;
};

class VplTracer {
 public:
  // Uploads the BVH, the polygon table and the emitters; throws InputError if nothing emits.
  VplTracer(const Scene& scene, const InstantSettings& settings);
  // Traces the paths into the VPL buffer (SSBO_VPLS) and reads the path ends back.
  VplStats trace();
  // The same trace without reading anything back (no wait for the GPU: the bench's full frame).
  void dispatch();
  // Binds the polygon table, its vertices and the VPLs (scene.glsl, vpl.glsl).
  void bind() const;
  std::vector<GpuVpl> readVpls() const;
  const VplLevels& levels() const { return levels_; }
  double rhoAvg() const { return rhoAvg_; }
  const Bvh& bvh() const { return bvh_; }
  double sceneDiagonal() const { return diagonal_; }

 private:
  const Scene& scene_;
  InstantSettings settings_;
  Bvh bvh_;
  VplLevels levels_;
  double rhoAvg_ = 0, diagonal_ = 0, emitted_ = 0;
  unsigned emitters_ = 0;
  gl::Program program_;
  gl::Buffer polygons_, polygonVertices_, emitterTable_, vpls_, pathEnds_;
  BvhBuffers bvhBuffers_;
};

}  // namespace hemirad
