// Checkpoints: a solve's whole state (B, dB, the solver's own state such as the shot count and
// convergence history) with what it was made from (scene hash, parameters), written atomically
// so a kill at any moment leaves the previous checkpoint intact. A resumed solve continues
// bitwise where the interrupted one stopped.
#pragma once
#include <cstdint>
#include <glm/glm.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "src/scene/Scene.h"

namespace hemirad {

struct Checkpoint {
  // What must match to resume: {"scene_hash": ..., parameter: value, ...}.
  nlohmann::json identity;
  unsigned shots = 0;
  std::vector<glm::vec4> radiosity, deltaB;  // atlas order
  std::vector<std::uint8_t> solver;          // Solver::saveState()
};

// FNV-1a 64 over the polygons (vertices, material, object) and materials: the scene as solved,
// independent of how its files were formatted.
std::uint64_t sceneHash(const Scene& scene);

// Writes atomically (temporary file, fsync, rename).
void writeCheckpoint(const std::string& path, const Checkpoint& checkpoint);
// Throws InputError for a missing, truncated, corrupt or foreign file.
Checkpoint readCheckpoint(const std::string& path);
// Throws InputError naming the first field where `saved` (from a checkpoint) differs from
// `current` (this run).
void checkResumable(const std::string& path, const nlohmann::json& saved, const nlohmann::json& current);

}  // namespace hemirad
