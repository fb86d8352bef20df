#include "src/output/GltfWriter.h"

#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cstring>
#include <filesystem>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <map>
#include <numeric>
#include <sstream>
#include <utility>

#include "src/base/AtomicFile.h"
#include "src/base/Error.h"
#include "src/output/ExportPieces.h"
#include "src/output/ImageFile.h"

namespace hemirad {

namespace {

constexpr int kFloat = TINYGLTF_COMPONENT_TYPE_FLOAT, kUint = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;

// One primitive's vertex streams (a material's polygons, fanned).
struct Streams {
  std::vector<float> position, normal, uv0, uv1;
  std::vector<std::uint32_t> indices;
};

// Appends `bytes` as a buffer view of buffer 0 and an accessor over it; returns the accessor.
int addAccessor(tinygltf::Model& m, const void* data, std::size_t bytes, int componentType, int type, std::size_t count,
                int target) {
  auto& buffer = m.buffers[0].data;
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = buffer.size();
  view.byteLength = bytes;
  view.target = target;
  buffer.insert(buffer.end(), static_cast<const unsigned char*>(data), static_cast<const unsigned char*>(data) + bytes);
  m.bufferViews.push_back(view);
  tinygltf::Accessor a;
  a.bufferView = int(m.bufferViews.size()) - 1;
  a.componentType = componentType;
  a.type = type;
  a.count = count;
  m.accessors.push_back(a);
  return int(m.accessors.size()) - 1;
}

int addFloats(tinygltf::Model& m, const std::vector<float>& v, int components, int type) {
  return addAccessor(m, v.data(), v.size() * sizeof(float), kFloat, type, v.size() / std::size_t(components),
                     TINYGLTF_TARGET_ARRAY_BUFFER);
}

// Polygon `id`'s pieces (src/output/ExportPieces.h) fanned (a b c, a c d, ...) into `s`: flat
// normal, TEXCOORD_0 its chart coordinates in scene units (for material textures), TEXCOORD_1 the
// lightmap's. Pieces share their vertices where equal, so an uncut polygon is its own vertices
// and fan; a piece with vertices along its sides (welded to a neighbour's cuts) is fanned from its
// centroid, which no side passes through.
void addPolygon(Streams& s, const Scene& scene, const Atlas& atlas, const Lightmap& map, int id,
                const ExportPolygon& pieces) {
  const ScenePolygon& p = scene.polygons()[std::size_t(id)];
  std::map<std::array<double, 5>, std::uint32_t> index;
  auto vertex = [&](const SurfacePoint& v) {
    const std::array<double, 5> key{v.position.x, v.position.y, v.position.z, v.atlas.x, v.atlas.y};
    const auto [it, added] = index.try_emplace(key, std::uint32_t(s.position.size() / 3));
    if (!added) return it->second;
    const glm::dvec2 uv = map.uv(atlas, id, v.atlas);
    const glm::dvec3 at = v.position / scene.unitScale;  // in the file's units
    s.position.insert(s.position.end(), {float(at.x), float(at.y), float(at.z)});
    s.normal.insert(s.normal.end(), {float(p.normal.x), float(p.normal.y), float(p.normal.z)});
    s.uv0.insert(s.uv0.end(), {float(v.plane.x / scene.unitScale), float(v.plane.y / scene.unitScale)});
    s.uv1.insert(s.uv1.end(), {float(uv.x), float(uv.y)});
    return it->second;
  };
  for (std::size_t k = 0; k < pieces.pieces.size(); ++k) {
    const SurfacePiece& piece = pieces.pieces[k];
    if (!pieces.welded[k]) {
      for (std::size_t i = 1; i + 1 < piece.size(); ++i)
        s.indices.insert(s.indices.end(), {vertex(piece[0]), vertex(piece[i]), vertex(piece[i + 1])});
      continue;
    }
    SurfacePoint centre{};
    for (const SurfacePoint& v : piece)
      centre.position += v.position / double(piece.size()), centre.atlas += v.atlas / double(piece.size()),
          centre.plane += v.plane / double(piece.size());
    for (std::size_t i = 0; i < piece.size(); ++i)
      s.indices.insert(s.indices.end(), {vertex(centre), vertex(piece[i]), vertex(piece[(i + 1) % piece.size()])});
  }
}

tinygltf::Primitive primitive(tinygltf::Model& m, const Streams& s, int material) {
  tinygltf::Primitive prim;
  prim.mode = TINYGLTF_MODE_TRIANGLES;
  prim.material = material;
  const int position = addFloats(m, s.position, 3, TINYGLTF_TYPE_VEC3);
  for (int c = 0; c < 3; ++c) {  // POSITION needs its bounds
    double lo = 1e300, hi = -1e300;
    for (std::size_t i = std::size_t(c); i < s.position.size(); i += 3)
      lo = std::min(lo, double(s.position[i])), hi = std::max(hi, double(s.position[i]));
    m.accessors[std::size_t(position)].minValues.push_back(lo);
    m.accessors[std::size_t(position)].maxValues.push_back(hi);
  }
  prim.attributes["POSITION"] = position;
  prim.attributes["NORMAL"] = addFloats(m, s.normal, 3, TINYGLTF_TYPE_VEC3);
  prim.attributes["TEXCOORD_0"] = addFloats(m, s.uv0, 2, TINYGLTF_TYPE_VEC2);
  prim.attributes["TEXCOORD_1"] = addFloats(m, s.uv1, 2, TINYGLTF_TYPE_VEC2);
  prim.indices = addAccessor(m, s.indices.data(), s.indices.size() * sizeof(std::uint32_t), kUint, TINYGLTF_TYPE_SCALAR,
                             s.indices.size(), TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
  return prim;
}

tinygltf::Value rgb(const glm::dvec3& c) {
  return tinygltf::Value(tinygltf::Value::Array{tinygltf::Value(c.x), tinygltf::Value(c.y), tinygltf::Value(c.z)});
}

// The albedo as base colour, the lightmap as emission through TEXCOORD_1 (what a viewer with no
// lights shows: the solution as hemirad's camera image has it); rho and E exactly in extras, which
// hemirad reads back, so its own .glb reloads as the scene it came from.
tinygltf::Material material(const Material& mat, const std::string& exrName, double exposureScale) {
  tinygltf::Material out;
  out.name = mat.name;
  const glm::dvec3 albedo = glm::clamp(mat.reflectance, 0.0, 1.0);
  out.pbrMetallicRoughness.baseColorFactor = {albedo.x, albedo.y, albedo.z, 1};
  out.pbrMetallicRoughness.metallicFactor = 0;
  out.pbrMetallicRoughness.roughnessFactor = 1;
  out.emissiveFactor = {1, 1, 1};
  out.emissiveTexture.index = 0;
  out.emissiveTexture.texCoord = 1;
  out.doubleSided = true;  // hemirad's faces are seen, and lit, from both sides
  tinygltf::Value::Object hemirad{{"reflectance", rgb(mat.reflectance)},
                                  {"emission", rgb(mat.emission)},
                                  {"lightmap_hdr", tinygltf::Value(exrName)},
                                  {"lightmap_texcoord", tinygltf::Value(1)},
                                  {"png_exposure_scale", tinygltf::Value(exposureScale)}};
  out.extras = tinygltf::Value(tinygltf::Value::Object{{"hemirad", tinygltf::Value(hemirad)}});
  return out;
}

// The solve's camera as a node looking down its -z (glTF's convention, as glm::lookAt's).
void addCamera(tinygltf::Model& m, const Scene& scene, const Camera& camera, double aspect) {
  tinygltf::Camera cam;
  cam.type = "perspective";
  cam.perspective.yfov = glm::radians(camera.fovY);
  cam.perspective.aspectRatio = aspect;
  // Near enough that a viewer's orbit towards the scene does not clip it (hemirad's own near plane,
  // half the way to the bounds, is only right for this one eye): 1 % of the scene's diagonal.
  const double diagonal = glm::length(scene.boundsMax() - scene.boundsMin());
  cam.perspective.znear = std::min(nearPlane(camera, scene.boundsMin(), scene.boundsMax()), 0.01 * diagonal);
  // tinygltf always writes zfar, and 0 (infinite) is not a valid one: twice the farthest corner.
  double farthest = 0;
  for (int k = 0; k < 8; ++k)
    farthest = std::max(farthest, glm::length(glm::dvec3(k & 1 ? scene.boundsMax().x : scene.boundsMin().x,
                                                         k & 2 ? scene.boundsMax().y : scene.boundsMin().y,
                                                         k & 4 ? scene.boundsMax().z : scene.boundsMin().z) -
                                              camera.eye));
  cam.perspective.zfar = std::max(2 * farthest, 2 * cam.perspective.znear) / scene.unitScale;  // the file's units
  cam.perspective.znear /= scene.unitScale;
  m.cameras.push_back(cam);
  const glm::dmat4 world = glm::inverse(glm::lookAt(camera.eye, camera.target, camera.up));
  const glm::dquat q = glm::normalize(glm::quat_cast(glm::dmat3(world)));
  tinygltf::Node node;
  node.name = "camera";
  node.camera = 0;
  const glm::dvec3 eye = camera.eye / scene.unitScale;
  node.translation = {eye.x, eye.y, eye.z};
  node.rotation = {q.x, q.y, q.z, q.w};
  m.nodes.push_back(node);
}

// One mesh and one named node per scene object (what engines select, hide and instance), a
// primitive per material it uses. Materials keep the scene's indices. Polygons are visited in
// (object, material, id) order, so memory grows with the polygons, not objects x materials.
void addObjects(tinygltf::Model& m, const Scene& scene, const Atlas& atlas, const Lightmap& map) {
  const std::vector<ScenePolygon>& polygons = scene.polygons();
  const std::vector<ExportPolygon> pieces = exportPieces(scene, atlas, map);
  std::vector<std::uint32_t> order(polygons.size());
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    return std::pair(polygons[a].object, polygons[a].material) < std::pair(polygons[b].object, polygons[b].material);
  });
  for (std::size_t k = 0; k < order.size();) {
    const int object = polygons[order[k]].object;
    tinygltf::Mesh mesh;
    mesh.name = scene.objects[std::size_t(object)].name;
    while (k < order.size() && polygons[order[k]].object == object) {
      const int material = polygons[order[k]].material;
      Streams streams;
      for (; k < order.size() && polygons[order[k]].object == object && polygons[order[k]].material == material; ++k)
        addPolygon(streams, scene, atlas, map, int(order[k]), pieces[order[k]]);
      if (!streams.indices.empty()) mesh.primitives.push_back(primitive(m, streams, material));
    }
    if (mesh.primitives.empty()) continue;
    m.meshes.push_back(mesh);
    tinygltf::Node node;
    node.name = mesh.name;
    node.mesh = int(m.meshes.size()) - 1;
    m.nodes.push_back(node);
  }
}

// The lightmap PNG inside the binary chunk, so a .glb copied alone still shows its light.
void embedLightmap(tinygltf::Model& m, const std::string& png) {
  auto& buffer = m.buffers[0].data;
  buffer.resize((buffer.size() + 3) / 4 * 4);  // the next view starts 4-byte aligned
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = buffer.size();
  view.byteLength = png.size();
  buffer.insert(buffer.end(), png.begin(), png.end());
  m.bufferViews.push_back(view);
  tinygltf::Image image;
  image.name = "lightmap";
  image.bufferView = int(m.bufferViews.size()) - 1;
  image.mimeType = "image/png";
  m.images.push_back(image);
}

tinygltf::Model model(const Scene& scene, const Atlas& atlas, const Lightmap& map, const Camera& camera, double aspect,
                      double exposureScale, const std::string& exrName, const std::string& png) {
  tinygltf::Model m;
  m.asset.version = "2.0";
  m.asset.generator = "hemirad";
  m.buffers.resize(1);
  for (std::size_t mat = 0; mat < scene.materials.size(); ++mat)
    m.materials.push_back(material(scene.materials[mat], exrName, exposureScale));
  addObjects(m, scene, atlas, map);
  embedLightmap(m, png);
  tinygltf::Sampler sampler;  // bilinear, no mipmaps: the clamped coordinates guard level 0 only
  sampler.magFilter = sampler.minFilter = TINYGLTF_TEXTURE_FILTER_LINEAR;
  sampler.wrapS = sampler.wrapT = TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE;  // with gutters, the border's are cut away
  m.samplers.push_back(sampler);
  tinygltf::Texture texture;
  texture.source = 0;
  texture.sampler = 0;
  m.textures.push_back(texture);
  addCamera(m, scene, camera, aspect);
  tinygltf::Scene root;
  for (std::size_t n = 0; n < m.nodes.size(); ++n) root.nodes.push_back(int(n));
  m.scenes.push_back(root);
  m.defaultScene = 0;
  return m;
}

}  // namespace

GltfPaths gltfPaths(const std::string& glb) {
  if (isStream(glb) || glb == "-") return {glb, ""};  // a stream gets no sidecar: the .glb alone
  std::string base = glb;
  std::string ext = std::filesystem::path(glb).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  if (ext == ".glb") base.resize(glb.size() - 4);
  return {glb, base + ".lightmap.exr"};
}

GltfFiles encodeGltf(const GltfPaths& paths, const Scene& scene, const Atlas& atlas, const std::vector<glm::vec4>& B,
                     const Camera& camera, double aspect, double exposureScale, const LightmapOptions& lightmap) {
  GltfFiles files{buildLightmap(atlas, B, lightmap), "", ""};
  Image image{files.map.width, files.map.height, std::vector<float>(files.map.rgb.size() * 3)};
  std::memcpy(image.rgb.data(), files.map.rgb.data(), image.rgb.size() * sizeof(float));
  if (!paths.exr.empty()) files.exr = encodeExr(image);
  const std::string exrName = paths.exr.empty() ? "" : std::filesystem::path(paths.exr).filename().string();
  const tinygltf::Model m =
      model(scene, atlas, files.map, camera, aspect, exposureScale, exrName, encodePng(image, exposureScale));
  std::ostringstream out;
  if (!tinygltf::TinyGLTF().WriteGltfSceneToStream(&m, out, false, true)) fail("{}: cannot encode the glTF", paths.glb);
  files.glb = std::move(out).str();
  return files;
}

Lightmap writeGltf(const GltfPaths& paths, const Scene& scene, const Atlas& atlas, const std::vector<glm::vec4>& B,
                   const Camera& camera, double aspect, double exposureScale, const LightmapOptions& lightmap) {
  GltfFiles files = encodeGltf(paths, scene, atlas, B, camera, aspect, exposureScale, lightmap);
  OutputBatch batch;
  stageGltf(batch, paths, files);
  batch.commit();
  return files.map;
}

void stageGltf(OutputBatch& batch, const GltfPaths& paths, const GltfFiles& files) {
  batch.add("--gltf", paths.glb, files.glb);
  if (!paths.exr.empty()) batch.add("--gltf", paths.exr, files.exr);
}

}  // namespace hemirad
