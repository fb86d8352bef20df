#include "src/scene/AtlasUse.h"

namespace hemirad {

AtlasUse atlasUse(const Atlas& atlas) {
  AtlasUse u;
  u.texels = std::size_t(atlas.width) * std::size_t(atlas.height);
  u.elements = atlas.elements;
  for (const Chart& c : atlas.charts) u.chartCells += std::size_t(c.size.x) * std::size_t(c.size.y);
  return u;
}

}  // namespace hemirad
