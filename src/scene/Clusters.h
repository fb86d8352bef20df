// Clusters (issue 29): a scene of many small disconnected parts (a plant's leaves, an orchid's
// petals, the facets of a screw head) has more charts than a coarse --elements asks for, and a
// chart holds at least one element. Small charts of one object and material that face alike and
// lie within one texel's cube share one element instead: their triangles are mapped into one
// cell (a UV chart whose triangles overlap there, ChartMapping::clustered), so the element is
// all their pieces (true areas summed) and `--elements N` means about N on any mesh.
// The element receives at the centroid of its member nearest the cluster's centroid, with that
// member's normal: a point on the surface, as every element's centre is, never inside a small
// closed part.
#pragma once
#include <vector>

#include "src/scene/Atlas.h"
#include "src/scene/Charts.h"
#include "src/scene/Scene.h"

namespace hemirad {

// Sets of the indices of `groups` that share one element at texel size ts, each of two or more
// charts, in the order of their first member. oneCell[i]: chart i takes one cell at ts. Charts
// join when they are of one object and one material, their seed normals'
// dominant axis is the same (six cones: members face within 110 degrees of each other), and their
// centroids lie in one cube of side ts of a grid fixed in the scene.
std::vector<std::vector<int>> smallChartClusters(const Scene& scene, const std::vector<ChartGroup>& groups,
                                                 const std::vector<char>& oneCell, double ts);

// The chart of a cluster: every member polygon's triangles, each mapped by its own plane's frame,
// scaled to fit 0.9 of a cell, and centred on one cell of side ts.
ChartGroup clusterGroup(const Scene& scene, const std::vector<ChartGroup>& groups, const std::vector<int>& members,
                        double ts);

// Where a cluster receives: its member polygon whose centroid lies nearest `centre` (the
// cluster's area centroid), so a cluster's corner part, the most shadowed or the least, does not
// stand for the rest.
int clusterReceiver(const Scene& scene, const std::vector<int>& polygons, const glm::dvec3& centre);
// The area centroid of a planar polygon.
glm::dvec3 polygonCentroid(const Poly3& p, const glm::dvec3& normal);

// Per occluder (Scene::occluder): how far the parts of its cluster reach behind its plane, where
// it receives and shoots for them; 0 off clusters. A cluster's shooter faces what lies in front
// of any of its parts, not only of its own plane (shaders/scene.glsl's reachBehind, HostTrace).
std::vector<float> clusterReachBehind(const Scene& scene, const Atlas& atlas);

}  // namespace hemirad
