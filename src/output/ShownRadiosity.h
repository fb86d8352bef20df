// What camera images, the PLY and lightmaps show of a solution: buried texels filled from their
// neighbours (src/output/BuriedTexels.h), then seams stitched (src/output/SeamStitch.h). Both
// are found once per layout, so live views (the viewer, walkthroughs, animations) apply them
// every frame. The solution's elements, the report's means and the radiosity hash keep the
// solved values.
#pragma once
#include <glm/glm.hpp>
#include <vector>

#include "src/output/BuriedTexels.h"
#include "src/output/SeamStitch.h"

namespace hemirad {

class ShownRadiosity {
 public:
  ShownRadiosity(const Scene& scene, const Atlas& atlas, const std::vector<SmoothEdge>& edges)
      : fill_(scene, atlas), stitch_(atlas, edges) {}
  ShownRadiosity(const Scene& scene, const Atlas& atlas) : ShownRadiosity(scene, atlas, smoothEdges(scene)) {}
  std::vector<glm::vec4> operator()(std::vector<glm::vec4> values) const { return stitch_(fill_(std::move(values))); }
  bool identity() const { return fill_.empty() && stitch_.empty(); }

 private:
  BuriedFill fill_;
  SeamStitcher stitch_;
};

// ShownRadiosity(scene, atlas)(values), for one use.
inline std::vector<glm::vec4> shownRadiosity(const Scene& scene, const Atlas& atlas, std::vector<glm::vec4> values) {
  return ShownRadiosity(scene, atlas)(std::move(values));
}

}  // namespace hemirad
