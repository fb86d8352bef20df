// A light path: keyframed offsets of the scene's emitters, one keyframe per line,
//
//   TIME  DX DY DZ   # comment
//
// TIME in seconds (increasing), then the translation of every emitting polygon from where the
// OBJ puts it. Between keyframes the offset is their linear blend; before the first and after
// the last it is held. Moving only translates, so the atlas keeps its layout frame to frame
// and the radiosity of each element carries over.
#pragma once
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "src/scene/Atlas.h"
#include "src/scene/Scene.h"

namespace hemirad {

struct LightKey {
  double time = 0;
  glm::dvec3 offset{0.0};
};

struct LightPath {
  std::vector<LightKey> keys;  // at least one
  double duration() const { return keys.back().time; }
  glm::dvec3 at(double time) const;
};

// Throws InputError naming the file and line.
LightPath readLightPath(const std::string& path);
// `scene` with every polygon of an emissive material moved by `offset`.
Scene withLightsMoved(const Scene& scene, const glm::dvec3& offset);
// `atlas` (of `scene`) for withLightsMoved(scene, offset): the same layout, the emitters' charts
// and element centres moved. Rebuilding the atlas instead could round a chart's size differently.
Atlas withLightsMoved(const Atlas& atlas, const Scene& scene, const glm::dvec3& offset);

}  // namespace hemirad
