// The scene: planar convex polygons with a material and an object each, held in an OpenMesh
// polygon mesh (face properties carry the material and object ids) with a per-polygon cache of
// plane data for the atlas and the GPU.
#pragma once
#include <OpenMesh/Core/Mesh/PolyMesh_ArrayKernelT.hh>
#include <array>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "src/base/OutputPaths.h"
#include "src/base/Polygon.h"
#include "src/scene/Warnings.h"

namespace hemirad {

struct MeshTraits : OpenMesh::DefaultTraits {
  using Point = OpenMesh::Vec3d;
  using Normal = OpenMesh::Vec3d;
};
using Mesh = OpenMesh::PolyMesh_ArrayKernelT<MeshTraits>;

struct Material {
  std::string name;
  glm::dvec3 reflectance{0.0};  // rho, from Kd
  glm::dvec3 emission{0.0};     // E, from Ke (or Ka with --emission ka)
  bool emissive() const { return emission.x > 0 || emission.y > 0 || emission.z > 0; }
};

// The warning for a material with a reflectance channel of exactly 1 (above 1 is refused).
inline constexpr const char* kReflectanceOne =
    "reflectance 1: no energy is absorbed there; a closed scene of such materials never converges";

struct SceneObject {
  std::string name;  // OBJ `o`/`g` name
};

// One planar convex polygon: one chart in the atlas, one id in the item buffer.
struct ScenePolygon {
  Poly3 vertices;     // counter-clockwise seen from the front (emitting, receiving) side
  glm::dvec3 normal;  // unit front normal
  double area = 0;
  int material = 0;
  int object = 0;
  // Signed distance of p in front of the plane (negative behind it).
  double height(const glm::dvec3& p) const { return glm::dot(normal, p - vertices[0]); }
  // p moved along the normal onto the plane (as shaders/scene.glsl's ontoPlane).
  glm::dvec3 ontoPlane(const glm::dvec3& p) const { return p - normal * height(p); }
};

class Scene {
 public:
  std::string path;  // the OBJ it came from ("" for scenes built in code)
  std::vector<Material> materials;
  std::vector<SceneObject> objects;
  std::vector<SceneWarning> warnings;  // what loading repaired or skipped (printWarnings groups them)
  std::string emissionKey = "Ke";      // what E was read from: Ke, Ka (--emission ka), emissiveFactor (glTF)
  // Every file the scene names (the scene, MTLs and their texture maps, glTF buffers and
  // images), with what it is: outputs may never be written over them.
  std::vector<InputPath> sources;
  // Scene units per file unit: 1, or the power of two normalizeUnits (src/scene/Units.h) applied.
  double unitScale = 1;
  std::string camera;  // the scene file's own camera (glTF) as --camera text; "" for none
  // The input's lightmap UVs (glTF TEXCOORD_1, for --uv input): per polygon, per vertex; a
  // polygon without them has none, and a scene without any has an empty list.
  std::vector<Poly2> lightmapUv;
  // Discontinuity lines (D0 contact lines, src/scene/ContactCuts.h): edges along them are where
  // the light jumps, so seam stitching leaves them be.
  std::vector<std::array<glm::dvec3, 2>> creases;
  // A refined layout (src/scene/Leaves.h) cuts polygons along its leaves; `wholes` keeps each cut
  // polygon whole, and wholeOf[p] names the whole polygon p was cut from (-1: p is not a cut
  // part; empty: none is). Item buffers draw the wholes in place of their parts, as occluders
  // [polygons().size(), occluderCount()): fewer triangles to draw, and a receiver's window
  // names one polygon to test where it named several parts (adaptive Cornell at 100k: 38 item
  // triangles, not 3,474; the item buffer's time on llvmpipe 0.70 -> 0.09 s).
  std::vector<ScenePolygon> wholes;
  std::vector<int> wholeOf;

  // Adds a polygon; returns false (and records nothing) if it has no area.
  bool addPolygon(const Poly3& vertices, int material, int object);
  int addMaterial(Material m);
  int addObject(std::string name);  // existing id if the name is known
  void rescale(double factor);      // every vertex times `factor` (areas times its square)

  const std::vector<ScenePolygon>& polygons() const { return polygons_; }
  // What item buffers draw, by id: the polygons, then the wholes; a cut part is not drawn.
  std::size_t occluderCount() const { return polygons_.size() + wholes.size(); }
  const ScenePolygon& occluder(std::size_t id) const {
    return id < polygons_.size() ? polygons_[id] : wholes[id - polygons_.size()];
  }
  bool drawn(std::size_t id) const { return id >= polygons_.size() || wholeOf.empty() || wholeOf[id] < 0; }
  const Mesh& mesh() const { return mesh_; }
  double totalArea() const;
  double emittedPower() const;  // sum of luminance(E) * A
  glm::dvec3 boundsMin() const;
  glm::dvec3 boundsMax() const;

 private:
  std::vector<ScenePolygon> polygons_;
  Mesh mesh_;
  OpenMesh::FPropHandleT<int> polygonProp_, materialProp_, objectProp_;
  bool propsAdded_ = false;
};

// A scene with `s`'s materials, objects and everything else but no polygons (for cut layouts).
Scene sceneLike(const Scene& s);

// Rec. 709 luminance weights, for every luminance on both sides (shaders get them as LUMINANCE).
inline constexpr double kLuminanceWeights[3] = {0.2126, 0.7152, 0.0722};
double luminance(const glm::dvec3& c);

}  // namespace hemirad
