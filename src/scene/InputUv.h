// --uv input (issue 29): charts from the input's own lightmap UVs (glTF TEXCOORD_1; an OBJ's
// texture coordinates, `vt`, which are its only UVs). Each UV
// island (triangles of one material and object joined by edges whose both ends share position
// and UV) is one chart, laid as the input lays it: its UVs times one scale for the whole scene,
// sqrt(surface area / UV area), so a UV length is on average the surface length it covers and
// --elements and --texel-size mean what they mean for projection charts. An island the input
// mirrors is mirrored back (a chart's grid is seen from the front).
#pragma once
#include <vector>

#include "src/scene/Charts.h"
#include "src/scene/Scene.h"

namespace hemirad {

// A UV triangle under this fraction of its (scaled) surface triangle's area is degenerate.
inline constexpr double kMinUvAreaRatio = 1e-6;

// The charts; throws InputError when a polygon has no UVs or a UV triangle is degenerate or
// folded against its island (overlaps are refused as the atlas cuts them, src/scene/Atlas.cpp).
std::vector<ChartGroup> inputUvCharts(const Scene& scene);

}  // namespace hemirad
