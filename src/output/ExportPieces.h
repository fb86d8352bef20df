// The .glb's surface pieces (src/output/GltfWriter.cpp): each polygon cut along its lightmap
// clamp lines (Lightmap::affinePieces), then welded: a cut vertex on an edge the polygon shares
// with another polygon (the same two corners) is put on that polygon's edge too, so the exported
// mesh has no T-junction, where rasterisers leave hairline cracks between the triangles.
#pragma once
#include <vector>

#include "src/output/Lightmap.h"
#include "src/scene/Scene.h"

namespace hemirad {

struct ExportPolygon {
  std::vector<SurfacePiece> pieces;  // convex, counter-clockwise as the polygon
  std::vector<char> welded;          // per piece: it gained vertices on its sides (fan it from inside)
};

// Per polygon of `scene`, its pieces.
std::vector<ExportPolygon> exportPieces(const Scene& scene, const Atlas& atlas, const Lightmap& map);

}  // namespace hemirad
