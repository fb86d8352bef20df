// The solution as a mesh: every element's cut of its polygon as a face, vertices shared within
// a polygon, each vertex carrying B sampled there (the same masked bilinear lookup as the
// camera render). Binary little-endian PLY with uchar red/green/blue (the tone-mapped colour
// that MeshLab and Blender show) and float radiosity_r/g/b (linear B).
#pragma once
#include <string>
#include <vector>

#include "src/scene/Atlas.h"
#include "src/scene/Scene.h"

namespace hemirad {

// The mesh of element cuts, welded, with tone-mapped colours and linear radiosity per vertex.
std::string encodePly(const Scene& scene, const Atlas& atlas, const std::vector<glm::vec4>& B, double exposureScale);
void writePly(const std::string& path, const Scene& scene, const Atlas& atlas, const std::vector<glm::vec4>& B,
              double exposureScale);

}  // namespace hemirad
