// The exact CPU reference for one shooter element, receiver by receiver: CGAL visibility
// between the surface points of the elements' centres and the exact (contour, occlusion-stratified) form factor from
// each receiver centre to the shooter element. What the GPU item buffer and exact form factor are checked against.
#pragma once
#include <vector>

#include "cpu/ExactVisibility.h"
#include "src/scene/Atlas.h"
#include "src/scene/Scene.h"

namespace hemirad {

struct PairSample {
  bool facing = false;  // each centre in front of the other's surface
  bool visible = false;
  double formFactor = 0;  // receiver dA to the shooter element
  double bound = 0;       // error bound of formFactor (0: exact)
};

class ExactReference {
 public:
  ExactReference(const Scene& scene, const Atlas& atlas);
  // One entry per atlas texel; texels without elements or on the shooter's polygon stay zero.
  std::vector<PairSample> fromShooter(std::size_t shooterTexel) const;
  const cpu::ExactVisibility& visibility() const { return visibility_; }

 private:
  const Scene& scene_;
  const Atlas& atlas_;
  cpu::ExactVisibility visibility_;
};

std::vector<std::vector<glm::dvec3>> polygonList(const Scene& scene);

}  // namespace hemirad
