// Vertices welded by position, and the polygons each welded edge joins: what charts grow across
// (Charts.h), what smooth normals average over (SmoothNormals.h) and where seams are stitched
// (src/output/SeamStitch.h).
#pragma once
#include <map>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "src/scene/Scene.h"

namespace hemirad {

using WeldedEdge = std::pair<int, int>;  // welded vertex ids, the smaller first

// Ids equal when positions agree to 1e-9 of the scene's size.
struct Welding {
  std::vector<std::vector<int>> ids;  // per polygon, per vertex
  std::vector<glm::dvec3> position;   // per id: the first position seen
};

Welding weldVertices(const Scene& scene);

// Per undirected welded edge, the polygons having it, in polygon order.
std::map<WeldedEdge, std::vector<int>> polygonsByEdge(const Welding& w);

}  // namespace hemirad
