// A pinhole camera. Given on the command line as `eye=x,y,z,target=x,y,z,up=x,y,z,fov=deg`
// (any keys may be left out), or in a sidecar file SCENE.camera next to SCENE.obj holding the
// same text (whitespace or commas between items, `#` starts a comment).
#pragma once
#include <glm/glm.hpp>
#include <optional>
#include <string>

#include "src/scene/Scene.h"

namespace hemirad {

struct Camera {
  glm::dvec3 eye{0, 0, 1}, target{0, 0, 0}, up{0, 1, 0};
  double fovY = 45.0;  // vertical field of view, degrees
  bool operator==(const Camera&) const = default;
  // Reversed-Z view-projection with the far plane at infinity ([0, 1] clip depth, GL_GREATER).
  glm::mat4 viewProjection(double aspect, double near) const;
  // The world direction (not normalised) of the ray through window point w of a width x height
  // image (pixel centres at .5, rows bottom-up as GL's) is corner + w.x dx + w.y dy: the rays of
  // viewProjection's pixels.
  struct PixelRays {
    glm::dvec3 corner, dx, dy;
  };
  PixelRays pixelRays(int width, int height) const;
};

// A near plane in front of everything within the bounds: half the eye's distance to them (any
// point in view is at least its distance x cos(half the diagonal field of view) away, so fields of
// view up to 120 degrees), or a millionth of their size when the eye is inside them.
double nearPlane(const Camera& camera, const glm::dvec3& boundsMin, const glm::dvec3& boundsMax);

// Parses `text` over `base` (keys not given keep base's values); throws InputError naming `what`.
Camera parseCamera(const std::string& text, const Camera& base, const std::string& what);
// Frames the scene's bounds from the front (+z side), looking down -z.
Camera frameScene(const Scene& scene);
// The camera for a solve: --camera text over the sidecar SCENE.camera over the framing.
Camera resolveCamera(const Scene& scene, const std::optional<std::string>& cameraFlag);
std::string sidecarCameraPath(const std::string& objPath);

}  // namespace hemirad
