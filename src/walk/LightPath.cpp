#include "src/walk/LightPath.h"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "src/base/Error.h"

namespace hemirad {

glm::dvec3 LightPath::at(double time) const {
  if (time <= keys.front().time) return keys.front().offset;
  for (std::size_t i = 1; i < keys.size(); ++i)
    if (time <= keys[i].time) {
      const double f = (time - keys[i - 1].time) / (keys[i].time - keys[i - 1].time);
      return keys[i - 1].offset + f * (keys[i].offset - keys[i - 1].offset);
    }
  return keys.back().offset;
}

LightPath readLightPath(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(fmt::format("--light-path {}: cannot be read", path));
  LightPath out;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    std::istringstream fields(line.substr(0, line.find('#')));
    std::vector<std::string> words;
    for (std::string w; fields >> w;) words.push_back(w);
    if (words.empty()) continue;  // blank or comment
    const std::string where = fmt::format("{}:{}", path, number);
    if (words.size() != 4) throw InputError(fmt::format("{}: a keyframe is TIME DX DY DZ, not '{}'", where, line));
    double v[4];
    for (int i = 0; i < 4; ++i) {
      char* end = nullptr;
      v[i] = std::strtod(words[i].c_str(), &end);
      if (end == words[i].c_str() || *end != '\0' || !std::isfinite(v[i]))
        throw InputError(fmt::format("{}: '{}' is not a number", where, words[i]));
    }
    if (v[0] < 0 || (!out.keys.empty() && v[0] <= out.keys.back().time))
      throw InputError(fmt::format("{}: keyframe times must be >= 0 and increase, not {}", where, v[0]));
    out.keys.push_back({v[0], {v[1], v[2], v[3]}});
  }
  if (out.keys.empty()) throw InputError(fmt::format("--light-path {}: no keyframes", path));
  return out;
}

Scene withLightsMoved(const Scene& scene, const glm::dvec3& offset) {
  Scene out;
  out.path = scene.path;
  out.materials = scene.materials;
  out.objects = scene.objects;
  out.unitScale = scene.unitScale;
  for (const ScenePolygon& p : scene.polygons()) {
    Poly3 v = p.vertices;
    if (scene.materials[std::size_t(p.material)].emissive())
      for (glm::dvec3& x : v) x += offset;
    out.addPolygon(v, p.material, p.object);
  }
  return out;
}

Atlas withLightsMoved(const Atlas& atlas, const Scene& scene, const glm::dvec3& offset) {
  Atlas out = atlas;
  auto emits = [&](std::size_t polygon) {
    return scene.materials[std::size_t(scene.polygons()[polygon].material)].emissive();
  };
  for (Chart& c : out.charts)  // a chart is one material: it moves whole
    if (emits(std::size_t(c.polygon))) {
      c.frame.origin += offset;
      for (Poly3& part : c.parts)
        for (glm::dvec3& v : part) v += offset;
    }
  for (std::size_t t = 0; t < out.positionArea.size(); ++t)
    if (out.polygonOf[t] != kNoPolygon && emits(out.polygonOf[t]))
      out.positionArea[t] += glm::vec4(glm::vec3(offset), 0.0f);
  return out;
}

}  // namespace hemirad
