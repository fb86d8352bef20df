// Where an atlas's texels go (issue 29's texel use): elements, cells of chart rectangles that
// hold no element (a chart's outline against its rectangle), and the rest (packing: gaps and
// gutters). `hemirad info` prints it, tests bound it.
#pragma once
#include <cstddef>

#include "src/scene/Atlas.h"

namespace hemirad {

struct AtlasUse {
  std::size_t texels = 0;      // width x height
  std::size_t elements = 0;    // texels that hold an element
  std::size_t chartCells = 0;  // cells of the charts' rectangles (elements and empty cells)
  double texelUse() const { return texels ? double(elements) / double(texels) : 0; }
  // Elements over chart cells: what the charts' outlines leave of their rectangles.
  double cellUse() const { return chartCells ? double(elements) / double(chartCells) : 0; }
  // Chart cells over texels: what packing (gaps, gutters) leaves of the atlas.
  double packing() const { return texels ? double(chartCells) / double(texels) : 0; }
};

AtlasUse atlasUse(const Atlas& atlas);

}  // namespace hemirad
