// What hemirad ships beside its binary: the scenes and the plotting script. Installed
// (cmake --install), <prefix>/bin/hemirad finds them in <prefix>/share/hemirad; run from its build
// folder, in the source tree it was built from. Never relative to the current directory, so
// `bench` and `experiment` run from any directory.
#pragma once
#include <string>

namespace hemirad {

// <prefix>/share/hemirad beside the running binary if it is there, else the source tree.
const std::string& dataDir();
// A relative scene path missing from the current directory but present under dataDir(): that
// one (bench's and experiment's default scenes, "scenes/cornell/cornell.obj"). Else unchanged.
std::string findScene(const std::string& path);

}  // namespace hemirad
