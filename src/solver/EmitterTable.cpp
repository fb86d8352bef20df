#include "src/solver/EmitterTable.h"

#include "src/base/Error.h"
#include "src/solver/Bvh.h"

namespace hemirad {

std::vector<GpuEmitter> emitterTable(const Scene& scene, double& power, const std::string& who) {
  std::vector<GpuEmitter> table;
  std::vector<double> weight;
  for (std::uint32_t id = 0; id < scene.polygons().size(); ++id) {
    const ScenePolygon& p = scene.polygons()[id];
    const glm::dvec3 E = scene.materials[p.material].emission;
    if (luminance(E) <= 0) continue;
    for (std::size_t k = 1; k + 1 < p.vertices.size(); ++k) {
      const glm::dvec3 a = p.vertices[0], b = p.vertices[k], c = p.vertices[k + 1];
      table.push_back({glm::vec4(glm::vec3(a), 0), glm::vec4(glm::vec3(b - a), uintBitsToFloat(id)),
                       glm::vec4(glm::vec3(c - a), 0), glm::vec4(glm::vec3(E / luminance(E)), 0)});
      weight.push_back(luminance(E) * 0.5 * glm::length(glm::cross(b - a, c - a)));
    }
  }
  if (table.empty()) throw InputError(who + " needs an emitter: no polygon's material emits");
  power = 0;
  for (double w : weight) power += w;
  double cumulative = 0;
  for (std::size_t i = 0; i < table.size(); ++i) {
    cumulative += weight[i];
    table[i].v0.w = i + 1 == table.size() ? 2.0f : float(cumulative / power);  // the last catches u ~ 1
    table[i].flux *= float(power);
  }
  return table;
}

}  // namespace hemirad
