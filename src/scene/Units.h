// The scene's units, normalized: float radiosity (GPU) breaks on scenes far from unit size (the
// Cornell box scaled by 1e8 "converged" in 4 shots with black walls; at 1e-25 areas underflow). A
// scene whose diagonal lies outside [kMinDiagonal, kMaxDiagonal] is rescaled on loading by a power
// of two (exact in floating point) to a diagonal in [1, 2); every other scene keeps its units
// bitwise. Scene::unitScale records the factor: what the user gives in the file's units (--texel-
// size, --camera, camera and light paths) is multiplied by it, what hemirad writes in them (PLY,
// glTF, info, the report's texel size and areas) is divided by it. docs/errors.md, "Scale".
#pragma once
#include "src/scene/Camera.h"
#include "src/scene/Scene.h"

namespace hemirad {

inline constexpr double kMinDiagonal = 0x1p-10, kMaxDiagonal = 0x1p20;  // ~0.001 to ~1e6
inline constexpr double kMaxEmission = 1e30;  // float B and power sums keep headroom below 3.4e38

// Rescales `scene` if its size calls for it; fails (InputError) on a diagonal that is not finite
// and positive, or an emission beyond kMaxEmission or below 1/kMaxEmission but positive.
void normalizeUnits(Scene& scene);

// A camera given in the file's units, in the scene's (and back).
Camera toSceneUnits(const Scene& scene, Camera c);
Camera toFileUnits(const Scene& scene, Camera c);

}  // namespace hemirad
