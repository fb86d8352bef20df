#include "src/walk/CameraPath.h"

#include <fmt/format.h>
#include <cmath>
#include <fstream>
#include <sstream>

#include "src/base/Error.h"

namespace hemirad {

Camera CameraPath::at(double time) const {
  std::size_t k = 1;
  while (k < keys.size() && keys[k].time < time) ++k;
  if (k == keys.size() || time <= keys.front().time)
    return time <= keys.front().time ? keys.front().camera : keys.back().camera;
  const Keyframe &a = keys[k - 1], &b = keys[k];
  const double s = (time - a.time) / (b.time - a.time);
  Camera c;
  c.eye = glm::mix(a.camera.eye, b.camera.eye, s);
  c.target = glm::mix(a.camera.target, b.camera.target, s);
  c.up = glm::mix(a.camera.up, b.camera.up, s);
  c.fovY = a.camera.fovY + (b.camera.fovY - a.camera.fovY) * s;
  return c;
}

CameraPath readCameraPath(const std::string& path, const Camera& base, double unitScale) {
  std::ifstream in(path);
  if (!in) throw InputError(fmt::format("--camera-path {}: cannot be read", path));
  CameraPath out;
  Camera previous = base;  // in the file's units while parsing
  previous.eye /= unitScale, previous.target /= unitScale;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    std::string text = line.substr(0, line.find('#'));
    std::istringstream fields(text);
    std::string first;
    if (!(fields >> first)) continue;  // blank or comment
    const std::string where = fmt::format("{}:{}", path, number);
    char* end = nullptr;
    const double time = std::strtod(first.c_str(), &end);
    if (end == first.c_str() || *end != '\0' || !std::isfinite(time) || time < 0)
      throw InputError(fmt::format("{}: a keyframe starts with its time in seconds, not '{}'", where, first));
    if (!out.keys.empty() && time <= out.keys.back().time)
      throw InputError(
          fmt::format("{}: keyframe times must increase ({} after {})", where, time, out.keys.back().time));
    std::string rest;
    std::getline(fields, rest);
    previous = parseCamera(rest, previous, where);
    Camera key = previous;
    key.eye *= unitScale, key.target *= unitScale;
    out.keys.push_back({time, key});
  }
  if (out.keys.empty()) throw InputError(fmt::format("--camera-path {}: no keyframes", path));
  return out;
}

}  // namespace hemirad
