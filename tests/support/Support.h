// Shared helpers for the tests: scenes built in code, a GPU solve in one call, and running
// the hemirad binary.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "gl/Backend.h"
#include "src/output/Image.h"
#include "src/scene/Atlas.h"
#include "src/scene/Camera.h"
#include "src/scene/Scene.h"
#include "src/solver/ProgressiveSolver.h"

namespace hemirad::test {

// A w x h rectangle at `origin`, spanned by unit axes u and v; its front faces u x v.
Poly3 rectangle(glm::dvec3 origin, glm::dvec3 u, glm::dvec3 v, double w, double h);
int material(Scene& scene, double rho, double emission);
// A closed unit cube, faces inward, every face emitting E with reflectance rho; face
// `lampFace` (0 floor, 1 ceiling, ...; -1 none) is instead a black lamp: rho 0, E 1.
Scene cube(double rho, double E, int lampFace = -1);
// A UV sphere of `slices` x `stacks` facets (quads, triangles at the poles), facing out (or in).
void addSphere(Scene& s, glm::dvec3 centre, double radius, int slices, int stacks, int material, int object,
               bool inward = false);
// An open vertical cylinder (no caps) of `slices` quads standing at `base`, facing out.
void addCylinder(Scene& s, glm::dvec3 base, double radius, double height, int slices, int material, int object);

struct Solved {
  Atlas atlas;
  std::vector<glm::vec4> B, dB;  // alpha: received importance I - R and unshot importance dI
  std::vector<float> direct;     // importance-driven: R per atlas texel
  Image view;                    // with a camera: the solution seen from it, 128 x 128
  SolveStatus status;
  std::vector<ObjectRadiosity> objects;
  std::uint64_t hash = 0;
};

// The backend shared by the [gl] tests (OSMesa; HEMIRAD_TEST_BACKEND=egl picks EGL).
gl::RenderBackend& backend();
// With `camera`: importance-driven solves look from it, and the result is rendered from it.
Solved solve(const Scene& scene, double texelSize, const ProgressiveSettings& settings, const Camera* camera = nullptr);
// The same on an atlas the caller built.
Solved solve(const Scene& scene, Atlas atlas, const ProgressiveSettings& settings, const Camera* camera = nullptr);
const ObjectRadiosity& object(const Solved& s, const std::string& name);

// What the disc form factor (docs/design.md#form-factor) hands on from element `s` in a convex scene (no
// occlusion): sum over receivers j of F_js A_j / A_s. Exact form factors give 1 in a closed box;
// the disc approximation gives a little less near edges.
double discRowSum(const Scene& scene, const Atlas& atlas, std::size_t s);
// Its area-weighted mean over the elements: sigma in E / (1 - rho sigma).
double meanDiscRowSum(const Scene& scene, const Atlas& atlas);

// What the gather hands on from element `s` with exact form factors (no occlusion): sum over
// receivers j of F(x_j -> element s) A_j / A_s, x_j the receivers' centroids (cpu::pointToPolygon,
// the double twin of shaders/formfactor.glsl). 1 in a closed box, up to the centroid rule.
double exactRowSum(const Scene& scene, const Atlas& atlas, std::size_t s);
double meanExactRowSum(const Scene& scene, const Atlas& atlas);  // area-weighted over the elements

struct Run {
  int exitCode = -1;
  std::string output;  // stdout and stderr together
};
// Runs `hemirad ARGS` through the shell (ARGS as typed), optionally with environment prefix.
Run hemirad(const std::string& args, const std::string& env = "");
// Runs a shell script; `$HEMIRAD` in it names the hemirad binary under test.
Run shell(const std::string& script);
std::string sourcePath(const std::string& relative);  // a path in the source tree
std::string tempPath(const std::string& name);        // a fresh path in the test temp folder

}  // namespace hemirad::test
