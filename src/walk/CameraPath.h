// A camera path: keyframes in a text file, one per line,
//
//   TIME  eye=x,y,z target=x,y,z up=x,y,z fov=degrees   # comment
//
// TIME in seconds from the start (increasing), then a camera in the `--camera` syntax; keys a
// line leaves out keep the previous keyframe's values (the first line's: the scene's camera).
// The camera between two keyframes is their linear blend (eye, target, up, field of view).
#pragma once
#include <string>
#include <vector>

#include "src/scene/Camera.h"

namespace hemirad {

struct Keyframe {
  double time = 0;
  Camera camera;
};

struct CameraPath {
  std::vector<Keyframe> keys;  // at least one
  double duration() const { return keys.back().time; }
  Camera at(double time) const;  // clamped to the path's ends
};

// Throws InputError naming the file and line.
// Keyframes are in the scene file's units: times `unitScale` (the scene's Scene::unitScale).
CameraPath readCameraPath(const std::string& path, const Camera& base, double unitScale = 1);

}  // namespace hemirad
