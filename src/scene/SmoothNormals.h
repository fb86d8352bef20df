// Smooth normals for curved charts (issue 29): a tessellated sphere's facets are flat, but the
// surface they stand for is not. A receiver on a curved chart takes the normal interpolated from
// its polygon's vertex normals (each the corner-angle-weighted mean of the normals of the
// polygons meeting there of one material and object within the chart angle), so radiosity
// varies smoothly across facet edges instead of stepping with the facet normals.
#pragma once
#include <glm/glm.hpp>
#include <vector>

#include "src/scene/Scene.h"

namespace hemirad {

// Per polygon, per vertex: its smooth normal (unit). angleDegrees: polygons whose normals lie
// within it of the polygon's own are averaged in (the polygon's own normal always is).
std::vector<std::vector<glm::dvec3>> smoothVertexNormals(const Scene& scene, double angleDegrees);

// The normal at point p on polygon `poly` (convex), interpolated from its vertex normals (a fan
// from vertex 0, barycentric in the triangle holding p).
glm::dvec3 smoothNormalAt(const ScenePolygon& poly, const std::vector<glm::dvec3>& vertexNormals, glm::dvec3 p);

}  // namespace hemirad
