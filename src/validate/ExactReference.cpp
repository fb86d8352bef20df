#include "src/validate/ExactReference.h"

#include <tbb/parallel_for.h>

#include "cpu/ExactFormFactor.h"

namespace hemirad {

std::vector<std::vector<glm::dvec3>> polygonList(const Scene& scene) {
  std::vector<std::vector<glm::dvec3>> out;
  for (const auto& p : scene.polygons()) out.push_back(p.vertices);
  return out;
}

ExactReference::ExactReference(const Scene& scene, const Atlas& atlas)
    : scene_(scene), atlas_(atlas), visibility_(polygonList(scene)) {}

std::vector<PairSample> ExactReference::fromShooter(std::size_t s) const {
  const int sx = int(s % atlas_.width), sy = int(s / atlas_.width);
  const int shooterPolygon = int(atlas_.polygonOf[s]);
  const glm::dvec3 ps(atlas_.positionArea[s]), ns = glm::normalize(glm::dvec3(atlas_.normalOf[s]));
  const std::vector<Poly3> element = atlas_.elementShape(scene_, sx, sy);
  const std::uint32_t shooterChart = atlas_.chartAt(s);
  std::vector<PairSample> out(atlas_.polygonOf.size());
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, out.size(), 256), [&](const tbb::blocked_range<std::size_t>& r) {
    for (std::size_t t = r.begin(); t != r.end(); ++t) {
      std::uint32_t rp = atlas_.polygonOf[t];
      if (rp == kNoPolygon || atlas_.chartOf[rp] == shooterChart) continue;
      const glm::dvec3 pr(atlas_.positionArea[t]), nr = glm::normalize(glm::dvec3(atlas_.normalOf[t]));
      PairSample& p = out[t];
      p.facing = cpu::facing(ps, ns, pr, nr);
      if (!p.facing) continue;
      p.visible = visibility_.visible(ps, shooterPolygon, pr, int(rp));
      auto seen = [&](const glm::dvec3& q) { return visibility_.visible(q, shooterPolygon, pr, int(rp)); };
      for (const Poly3& piece : element) {  // linear in the shape: the pieces' sum is the element's
        cpu::ElementFormFactor f = cpu::pointToElement(pr, nr, piece, glm::normalize(newellNormal(piece)), seen);
        p.formFactor += f.value;
        p.bound += f.bound;
      }
    }
  });
  return out;
}

}  // namespace hemirad
