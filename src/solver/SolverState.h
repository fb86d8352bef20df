// What every radiosity algorithm works on: the atlas and polygon table on the GPU, and the
// radiosity B and unshot radiosity dB atlases (RGBA32F, one texel per element). Progressive
// refinement is one Solver over it; stochastic iteration and instant radiosity plug in beside.
#pragma once
#include <cstdint>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "gl/Objects.h"
#include "src/scene/Atlas.h"
#include "src/scene/Scene.h"
#include "src/solver/ShaderContract.h"  // kMaxShapeVertices, kShapeStride

namespace hemirad {

class SolverState {
 public:
  // Needs a current GL context. Uploads the atlas and sets B = dB = E.
  SolverState(const Scene& scene, const Atlas& atlas);

  const Scene& scene;
  const Atlas& atlas;
  gl::Texture positionArea;    // RGBA32F element centre and area
  gl::Texture polygonOf;       // R32UI polygon id per texel
  gl::Texture normal;          // RGBA32F per texel the receiver normal (Atlas::normalOf)
  gl::Texture radiosity;       // RGBA32F B
  gl::Texture deltaB;          // RGBA32F dB (unshot)
  gl::Buffer polygons;         // per polygon: plane, reflectance, emission, vertex range
  gl::Buffer polygonVertices;  // every polygon's vertices (xyz), in polygon order
  double emittedPower = 0;     // sum over elements of luminance(E) * area
  double farDistance = 0;      // longer than any segment inside the scene

  // Binds what scene.glsl reads: the polygon table, its vertices and the atlas.
  void bindScene() const;
  std::vector<glm::vec4> readRadiosity() const;  // atlas order, row 0 first
  std::vector<glm::vec4> readDeltaB() const;
  // Replaces B and dB (a checkpoint's), atlas order; throws InputError if the sizes differ.
  void restore(const std::vector<glm::vec4>& B, const std::vector<glm::vec4>& dB);
};

// Shooter shapes for shaders/formfactor.glsl: per atlas rectangle (shooter block) a slot of
// kShapeStride vec4s, its header the vertex count, the piece count (bits) and the offset of the
// next piece (in vec4s, bits; 0: none), then the vertices of Atlas::blockOutline's first piece; the
// other pieces follow the rectangles' slots packed (a header linking the next, then its vertices),
// so a curved chart's many small pieces take a third of a slot each. A shape of more than kMaxShapePieces pieces or a
// piece of more than kMaxShapeVertices vertices gets count 0: the gather then takes the disc.
struct ShapeTable {
  std::vector<glm::vec4> slots;
  std::size_t discShapes = 0;  // shapes past the budget, shot with the disc form factor
};
ShapeTable shapeTable(const Scene& scene, const Atlas& atlas, const std::vector<glm::ivec4>& rects);
// The table holds `shape` as pieces (up to kMaxShapePieces of up to kMaxShapeVertices), else as a disc.
bool fitsShapeTable(const std::vector<Poly3>& shape);

// Area-weighted mean B per object (the report's `mean_radiosity`, docs/design.md#report), from a B readback.
struct ObjectRadiosity {
  std::string name;
  double area = 0;
  glm::dvec3 mean{0.0};
};
std::vector<ObjectRadiosity> objectRadiosity(const Scene& scene, const Atlas& atlas, const std::vector<glm::vec4>& B);
// FNV-1a 64 of the B of every element (bit patterns), for determinism checks.
std::uint64_t radiosityHash(const Atlas& atlas, const std::vector<glm::vec4>& B);

}  // namespace hemirad
