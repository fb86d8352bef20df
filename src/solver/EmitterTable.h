// The scene's emitters as triangles picked by power (shaders/emitters.glsl): where instant
// radiosity starts its light paths and where the reference samples direct light.
#pragma once
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "src/scene/Scene.h"

namespace hemirad {

// std430, whole vec4s. v0.w: the cumulative power fraction up to and including this triangle
// (2 for the last, which catches u ~ 1); e1.w: the polygon id (uint bits); flux.rgb: E W / lum(E),
// W = the total lum(E) A: a sample's power per unit of probability, as a VPL's times its count.
struct GpuEmitter {
  glm::vec4 v0, e1, e2, flux;
};
static_assert(sizeof(GpuEmitter) == 64);

// Emitter triangles with their cumulative power fraction; `power` gets W. Throws InputError
// "`who` needs an emitter: ..." when no polygon emits.
std::vector<GpuEmitter> emitterTable(const Scene& scene, double& power, const std::string& who);

}  // namespace hemirad
