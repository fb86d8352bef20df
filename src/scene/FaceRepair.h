// A face read from a scene file (OBJ or glTF) as scene polygons: kept whole when planar and
// convex, split into triangles with a warning when not, skipped with a warning when degenerate;
// a face repeating its vertex cycle (`f 1 2 3 1 2 3`) is read as the single cycle, with a warning.
#pragma once
#include <functional>
#include <string>

#include "src/scene/Scene.h"

namespace hemirad {

using FaceSite = std::function<std::string()>;  // "file:line" (or "file: mesh 2 triangle 5") of the face

void addFace(Scene& scene, const Poly3& poly, int material, int object, const FaceSite& where);
// True if `poly` would stay one polygon in addFace: planar and convex, with area.
bool isPlanarConvex(const Poly3& poly);

}  // namespace hemirad
