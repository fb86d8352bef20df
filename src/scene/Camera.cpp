#include "src/scene/Camera.h"

#include "src/scene/Units.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <sstream>
#include <vector>

#include "src/base/Error.h"

namespace hemirad {

double nearPlane(const Camera& camera, const glm::dvec3& boundsMin, const glm::dvec3& boundsMax) {
  const glm::dvec3 outside = glm::max(glm::max(boundsMin - camera.eye, camera.eye - boundsMax), glm::dvec3(0.0));
  return std::max(0.5 * glm::length(outside), 1e-6 * glm::length(boundsMax - boundsMin));
}

glm::mat4 Camera::viewProjection(double aspect, double near) const {
  glm::dmat4 view = glm::lookAt(eye, target, up);
  // Reversed Z with the far plane at infinity, for [0, 1] clip depth (gl/State.h, DepthRange::Reversed):
  // clip z = near and w = -z_eye, so depth = near / -z_eye.
  const double f = 1.0 / std::tan(glm::radians(fovY) / 2);
  glm::dmat4 proj(0.0);
  proj[0][0] = f / aspect;
  proj[1][1] = f;
  proj[2][3] = -1.0;
  proj[3][2] = near;
  return glm::mat4(proj * view);
}

Camera::PixelRays Camera::pixelRays(int width, int height) const {
  // glm::lookAt's basis: forward f, right s, up u; window x maps to NDC 2 x / width - 1.
  const glm::dvec3 f = glm::normalize(target - eye), s = glm::normalize(glm::cross(f, up)), u = glm::cross(s, f);
  const double tanY = std::tan(glm::radians(fovY) / 2), tanX = tanY * double(width) / height;
  return {f - s * tanX - u * tanY, s * (2 * tanX / width), u * (2 * tanY / height)};
}

Camera parseCamera(const std::string& text, const Camera& base, const std::string& what) {
  std::string clean;
  for (std::istringstream lines(text); !lines.eof();) {
    std::string line;
    std::getline(lines, line);
    clean += line.substr(0, line.find('#')) + ' ';
  }
  for (char& c : clean)
    if (c == ',' || c == '\t' || c == '\r') c = ' ';
  // "eye = 1 2 3" reads as "eye=1 2 3".
  for (size_t eq; (eq = clean.find(" =")) != std::string::npos;) clean.erase(eq, 1);
  for (size_t eq; (eq = clean.find("= ")) != std::string::npos;) clean.erase(eq + 1, 1);
  Camera cam = base;
  std::istringstream in(clean);
  std::string token, key;
  std::vector<double> values;
  auto flush = [&] {
    if (key.empty()) return;
    auto vec = [&](glm::dvec3& out) {
      if (values.size() != 3) fail("{}: '{}' needs three numbers", what, key);
      out = {values[0], values[1], values[2]};
    };
    if (key == "eye")
      vec(cam.eye);
    else if (key == "target")
      vec(cam.target);
    else if (key == "up")
      vec(cam.up);
    else if (key == "fov") {
      if (values.size() != 1 || !(values[0] > 0 && values[0] < 180))
        fail("{}: 'fov' needs one angle in (0, 180) degrees", what);
      cam.fovY = values[0];
    } else
      fail("{}: unknown camera key '{}' (eye, target, up, fov)", what, key);
    key.clear();
    values.clear();
  };
  while (in >> token) {
    auto eq = token.find('=');
    if (eq != std::string::npos) {
      flush();
      key = token.substr(0, eq);
      token = token.substr(eq + 1);
      if (token.empty()) continue;
    }
    if (key.empty()) fail("{}: '{}' does not follow a key (eye=, target=, up=, fov=)", what, token);
    char* end = nullptr;
    double v = std::strtod(token.c_str(), &end);
    if (end == token.c_str() || *end != '\0' || !std::isfinite(v)) fail("{}: '{}' is not a number", what, token);
    values.push_back(v);
  }
  flush();
  if (glm::length(cam.target - cam.eye) <= 0) fail("{}: eye and target coincide", what);
  if (glm::length(glm::cross(cam.target - cam.eye, cam.up)) <= 0)
    fail("{}: 'up' is parallel to the view direction", what);
  return cam;
}

Camera frameScene(const Scene& scene) {
  glm::dvec3 lo = scene.boundsMin(), hi = scene.boundsMax();
  glm::dvec3 centre = (lo + hi) * 0.5;
  double radius = 0.5 * glm::length(hi - lo);
  Camera cam;
  cam.fovY = 45.0;
  cam.target = centre;
  cam.eye = centre + glm::dvec3(0, 0, radius / std::sin(glm::radians(cam.fovY * 0.5)));
  cam.up = {0, 1, 0};
  return cam;
}

std::string sidecarCameraPath(const std::string& objPath) {
  return std::filesystem::path(objPath).replace_extension(".camera").string();
}

Camera resolveCamera(const Scene& scene, const std::optional<std::string>& cameraFlag) {
  Camera cam = toFileUnits(scene, frameScene(scene));  // what the user writes is in the file's units
  if (!scene.camera.empty()) cam = parseCamera(scene.camera, cam, scene.path);
  std::string sidecar = sidecarCameraPath(scene.path);
  if (!scene.path.empty() && std::filesystem::is_regular_file(sidecar)) {
    std::ifstream in(sidecar);
    std::stringstream text;
    text << in.rdbuf();
    cam = parseCamera(text.str(), cam, sidecar);
  }
  if (cameraFlag) cam = parseCamera(*cameraFlag, cam, "--camera");
  return toSceneUnits(scene, cam);
}

}  // namespace hemirad
