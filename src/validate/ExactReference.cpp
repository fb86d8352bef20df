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
  // Where light leaves and arrives: a curved chart's centre, the mean of its pieces' centroids, sits
  // off its facets (inside a convex object), and a segment from it crosses its own surface.
  const glm::dvec3 leaves = scene_.polygons()[std::size_t(shooterPolygon)].ontoPlane(ps);
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
      const std::uint32_t receiverChart = atlas_.chartOf[rp];
      // What the GPU's visibility tests (shaders/visibility.glsl) do not count either: the
      // receiver's own chart (a curved one's element centre sits off its facets) and any polygon
      // whose plane holds an end of the segment, which only touches it there (the item buffer clips
      // the shooter's plane away; a coplanar neighbour at the receiver's centre is a contact).
      auto between = [&](const glm::dvec3& q, const glm::dvec3& x, std::uint32_t passing) {
        return visibility_.visible(q, x, [&](int p) {
          const std::uint32_t c = atlas_.chartOf[std::size_t(p)];
          if (p == shooterPolygon || p == int(rp) || c == receiverChart || c == passing) return true;
          const ScenePolygon& poly = scene_.polygons()[std::size_t(p)];
          const double tolerance = 1e-9 * (1 + glm::length(poly.vertices[0]));
          return std::abs(poly.height(q)) <= tolerance || std::abs(poly.height(x)) <= tolerance;
        });
      };
      // Element to element: between the surface points the centres stand for, both charts passing
      // (point visibility cannot resolve a surface against itself), as the traced test asks; not
      // from a curved chart's centre inside its own object, which its facets would hide.
      p.visible = between(leaves, scene_.polygons()[rp].ontoPlane(pr), shooterChart);
      auto seen = [&](const glm::dvec3& q) { return between(q, pr, receiverChart); };  // no further chart
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
