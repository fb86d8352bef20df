#pragma once
#include <string>

#include "src/scene/Scene.h"

namespace hemirad {

enum class EmissionSource { Ke, Ka };  // Ka: the thesis's convention for lights

struct LoadOptions {
  EmissionSource emission = EmissionSource::Ke;
};

// OBJ+MTL through tinyobjloader (exact Kd/Ke/Ka, material and o/g names, untriangulated
// polygons) into a Scene. Throws InputError naming the file and line for what cannot be
// used; repairs (skipped degenerate faces, triangulated non-planar polygons) are warnings.
Scene loadScene(const std::string& objPath, const LoadOptions& options = {});

// Checks that the scene can be solved: it has polygons and at least one emitter.
void validateSolvable(const Scene& scene);
// Why a scene has no emitter, in the terms of what its E was read from (Ke, Ka or glTF's emissiveFactor).
std::string noEmitterReason(const Scene& scene);

}  // namespace hemirad
