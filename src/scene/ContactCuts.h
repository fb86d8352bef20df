// Discontinuity meshing of the D0 lines (issue 31; src/scene/Contacts.h finds them): each
// receiving chart's parts are cut along its contact lines (each line's supporting line, across
// only the pieces it crosses, so every piece stays convex), and the pieces become charts of
// their own: pieces that meet along a boundary that is no contact line (the lit floor around a
// block, cut by a footprint edge's extension) join one chart, while the pieces a contact line
// separates never share one. Every chart keeps its receiver's grid lattice, so a texel ends on
// the contact line instead of straddling lit and unlit floor. As with adaptive subdivision's
// refined layout (src/scene/Leaves.h), the cut scene's polygons and the charts stay one to one,
// with the receiver's material, object and normal: the solver, PLY, lightmap and camera follow.
#pragma once
#include <cstddef>
#include <optional>
#include <vector>

#include "src/scene/Atlas.h"
#include "src/scene/Contacts.h"
#include "src/scene/Scene.h"

namespace hemirad {

// Contacts (chains of lines meeting end to end) less than this many of the receiver's cells
// across are not cut: their straddling texels cover a few percent of a cell of floor.
inline constexpr double kMinContactCells = 1;

struct ContactLayout {
  Scene scene;  // its `creases` hold the contact lines (seam stitching keeps them sharp)
  std::vector<ChartSpec> specs;
  std::size_t lines = 0;   // contact lines that cut
  std::size_t charts = 0;  // receiving charts cut
  std::size_t pieces = 0;  // the pieces they were cut into
};

// The layout of `scene` (gridded by `atlas`) cut along `lines` (findContacts); none when no line
// cuts a chart (the layout stands as it is).
std::optional<ContactLayout> cutAlongContacts(const Scene& scene, const Atlas& atlas,
                                              const std::vector<ContactLine>& lines);

}  // namespace hemirad
