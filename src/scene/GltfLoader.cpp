#include "src/scene/GltfLoader.h"

#include <fmt/format.h>
#include <tiny_gltf.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "src/base/Error.h"
#include "src/scene/FaceRepair.h"
#include "src/scene/SceneFormat.h"

namespace hemirad {

namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return s;
}

// Textures are not used; skipping their decoding also keeps a broken image from failing the load.
bool ignoreImage(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) {
  return true;
}

std::string firstLine(std::string s) {
  s = s.substr(0, s.find('\n'));
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.pop_back();
  return s;
}

tinygltf::Model readModel(const std::string& path) {
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(ignoreImage, nullptr);
  tinygltf::Model model;
  std::string err, warning;
  const bool binary = lower(std::filesystem::path(path).extension().string()) == ".glb";
  const bool ok = binary ? loader.LoadBinaryFromFile(&model, &err, &warning, path)
                         : loader.LoadASCIIFromFile(&model, &err, &warning, path);
  // tinygltf reads no version: a glTF 1.0 file fails its parse, or loads empty.
  if (!binary) refuseGltf1(path, ok ? model.asset.version : "");
  if (!ok) fail("{}: {}", path, err.empty() ? std::string("not a glTF 2.0 file") : firstLine(err));
  return model;
}

// The bytes of accessor `index`, checked against its buffer: element k at data + k * stride.
struct View {
  const unsigned char* data = nullptr;
  std::size_t stride = 0, count = 0;
  int componentType = 0, type = 0;
};

View accessorView(const tinygltf::Model& m, int index, const std::string& path, const std::string& what) {
  if (index < 0 || std::size_t(index) >= m.accessors.size())
    fail("{}: {} refers to accessor {} of {}", path, what, index, m.accessors.size());
  const tinygltf::Accessor& a = m.accessors[std::size_t(index)];
  if (a.sparse.isSparse) fail("{}: {}: sparse accessors are not supported", path, what);
  if (a.bufferView < 0 || std::size_t(a.bufferView) >= m.bufferViews.size())
    fail("{}: {}: accessor {} has no buffer view", path, what, index);
  const tinygltf::BufferView& v = m.bufferViews[std::size_t(a.bufferView)];
  if (v.buffer < 0 || std::size_t(v.buffer) >= m.buffers.size())
    fail("{}: {}: buffer view {} has no buffer", path, what, a.bufferView);
  const int componentSize = tinygltf::GetComponentSizeInBytes(std::uint32_t(a.componentType));
  const int components = tinygltf::GetNumComponentsInType(std::uint32_t(a.type));
  if (componentSize <= 0 || components <= 0) fail("{}: {}: accessor {} has an unknown type", path, what, index);
  const std::size_t element = std::size_t(componentSize) * std::size_t(components);
  const std::size_t stride = v.byteStride ? v.byteStride : element;
  const std::size_t size = m.buffers[std::size_t(v.buffer)].data.size();
  const std::size_t start = v.byteOffset + a.byteOffset;
  const bool fits = v.byteOffset <= size && v.byteLength <= size - v.byteOffset && a.byteOffset <= v.byteLength &&
                    (a.count == 0 || (stride >= element && (a.count - 1) <= (v.byteLength - a.byteOffset) / stride &&
                                      (a.count - 1) * stride + element <= v.byteLength - a.byteOffset));
  if (!fits) fail("{}: {}: accessor {} reaches past the end of its buffer", path, what, index);
  return {m.buffers[std::size_t(v.buffer)].data.data() + start, stride, a.count, a.componentType, a.type};
}

std::vector<glm::dvec3> positions(const tinygltf::Model& m, int index, const std::string& path) {
  View v = accessorView(m, index, path, "POSITION");
  if (v.type != TINYGLTF_TYPE_VEC3 || v.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT)
    fail("{}: POSITION accessor {} is not float VEC3", path, index);
  std::vector<glm::dvec3> out(v.count);
  for (std::size_t k = 0; k < v.count; ++k) {
    float p[3];
    std::memcpy(p, v.data + k * v.stride, sizeof p);
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      fail("{}: POSITION accessor {}: vertex {} coordinate is not a finite number", path, index, k);
    out[k] = {p[0], p[1], p[2]};
  }
  return out;
}

// TEXCOORD_1, the lightmap UVs (--uv input): float, or normalized unsigned byte or short
// (glTF 2.0, 3.7.2.1); empty if the primitive has none.
std::vector<glm::dvec2> lightmapUvs(const tinygltf::Model& m, const tinygltf::Primitive& p, std::size_t vertices,
                                    const std::string& path) {
  auto it = p.attributes.find("TEXCOORD_1");
  if (it == p.attributes.end()) return {};
  View v = accessorView(m, it->second, path, "TEXCOORD_1");
  const int type = v.componentType;
  if (v.type != TINYGLTF_TYPE_VEC2 ||
      (type != TINYGLTF_COMPONENT_TYPE_FLOAT && type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
       type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT))
    fail("{}: TEXCOORD_1 accessor {} is not float, unsigned byte or unsigned short VEC2", path, it->second);
  if (v.count != vertices) fail("{}: TEXCOORD_1 has {} values for {} vertices", path, v.count, vertices);
  std::vector<glm::dvec2> out(v.count);
  for (std::size_t k = 0; k < v.count; ++k)
    for (int c = 0; c < 2; ++c) {
      const unsigned char* at = v.data + k * v.stride;
      double x = 0;
      if (type == TINYGLTF_COMPONENT_TYPE_FLOAT) {
        float f = 0;
        std::memcpy(&f, at + 4 * c, 4), x = f;
      } else if (type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) {
        std::uint16_t u = 0;
        std::memcpy(&u, at + 2 * c, 2), x = u / 65535.0;
      } else {
        x = at[c] / 255.0;
      }
      if (!std::isfinite(x)) fail("{}: TEXCOORD_1 accessor {}: value {} is not a finite number", path, it->second, k);
      out[k][c] = x;
    }
  return out;
}

// The UVs of the polygons addFace made (from `first` on) out of the fan of vertices `corners`:
// each vertex's, matched by position (addFace keeps positions, or splits into their triangles).
void recordUvs(Scene& scene, std::size_t first, const std::vector<std::uint32_t>& corners,
               const std::vector<glm::dvec3>& points, const std::vector<glm::dvec2>& uv) {
  scene.lightmapUv.resize(scene.polygons().size());
  for (std::size_t p = first; p < scene.polygons().size(); ++p) {
    Poly2 out;
    for (const glm::dvec3& x : scene.polygons()[p].vertices)
      for (std::uint32_t c : corners)
        if (points[c] == x) {
          out.push_back(uv[c]);
          break;
        }
    if (out.size() == scene.polygons()[p].vertices.size()) scene.lightmapUv[p] = std::move(out);
  }
}

// The vertices of the fan of `used` triangles from triangle `first` (fanPolygon's).
std::vector<std::uint32_t> fanCorners(const std::vector<std::uint32_t>& idx, std::size_t first, std::size_t used) {
  std::vector<std::uint32_t> out{idx[3 * first], idx[3 * first + 1], idx[3 * first + 2]};
  for (std::size_t k = 1; k < used; ++k) out.push_back(idx[3 * (first + k) + 2]);
  return out;
}

std::vector<std::uint32_t> indices(const tinygltf::Model& m, const tinygltf::Primitive& p, std::size_t vertices,
                                   const std::string& path) {
  std::vector<std::uint32_t> out;
  if (p.indices < 0) {
    for (std::size_t k = 0; k < vertices; ++k) out.push_back(std::uint32_t(k));
    return out;
  }
  View v = accessorView(m, p.indices, path, "indices");
  const int size = tinygltf::GetComponentSizeInBytes(std::uint32_t(v.componentType));
  if (v.type != TINYGLTF_TYPE_SCALAR || (v.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
                                         v.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
                                         v.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT))
    fail("{}: indices accessor {} is not unsigned byte, short or int SCALAR", path, p.indices);
  for (std::size_t k = 0; k < v.count; ++k) {
    std::uint32_t i = 0;
    std::memcpy(&i, v.data + k * v.stride, std::size_t(size));  // little-endian hosts
    if (i >= vertices) fail("{}: index {} refers to vertex {} but POSITION has {}", path, k, i, vertices);
    out.push_back(i);
  }
  return out;
}

double finiteFactor(double x, const std::string& path, const std::string& what) {
  if (!std::isfinite(x)) fail("{}: {} is not a finite number", path, what);
  return x;
}

Material toMaterial(const tinygltf::Material& g, std::size_t index, const std::string& path, Scene& scene) {
  const std::string name = g.name.empty() ? fmt::format("material {}", index) : g.name;
  const std::string where = fmt::format("{}: material '{}'", path, name);
  Material out{name, glm::dvec3(1.0), glm::dvec3(0.0)};
  const auto& base = g.pbrMetallicRoughness.baseColorFactor;
  for (int c = 0; c < 3 && std::size_t(c) < base.size(); ++c)
    out.reflectance[c] = finiteFactor(base[std::size_t(c)], where, "baseColorFactor");
  double strength = 1;
  if (auto e = g.extensions.find("KHR_materials_emissive_strength");
      e != g.extensions.end() && e->second.Has("emissiveStrength"))
    strength = finiteFactor(e->second.Get("emissiveStrength").GetNumberAsDouble(), where, "emissiveStrength");
  for (int c = 0; c < 3 && std::size_t(c) < g.emissiveFactor.size(); ++c)
    out.emission[c] = finiteFactor(g.emissiveFactor[std::size_t(c)], where, "emissiveFactor") * strength;
  for (int c = 0; c < 3; ++c) {
    if (out.reflectance[c] > 1.0)
      fail("{}: reflectance baseColorFactor {} is above 1 (it would reflect more light than it receives)", where,
           out.reflectance[c]);
    if (out.reflectance[c] < 0.0) fail("{}: reflectance baseColorFactor {} is negative", where, out.reflectance[c]);
    if (out.emission[c] < 0.0) fail("{}: emission {} is negative", where, out.emission[c]);
  }
  // glTF's default baseColorFactor is 1: a material without one reflects everything.
  if (glm::any(glm::equal(out.reflectance, glm::dvec3(1.0))))
    scene.warnings.push_back({where, std::string(kReflectanceOne), "materials"});
  const bool hemiradLightmap = g.extras.Has("hemirad");  // its emissiveTexture is the baked solution
  if ((g.pbrMetallicRoughness.baseColorTexture.index >= 0 || g.emissiveTexture.index >= 0) && !hemiradLightmap)
    scene.warnings.push_back({where,
                              "texture ignored: hemirad uses the constant baseColorFactor and emissiveFactor of "
                              "each material, never textures",
                              "materials"});
  return out;
}

// hemirad's own .glb (src/output/GltfWriter.h) carries each material's exact rho and E in
// extras.hemirad, beside a lightmap as emissiveTexture that is not a light: read those instead,
// so the file reloads as the scene it came from.
void applyHemiradExtras(const tinygltf::Material& g, Material& out, const std::string& path) {
  if (!g.extras.Has("hemirad")) return;
  const tinygltf::Value& h = g.extras.Get("hemirad");
  auto rgb = [&](const char* key, glm::dvec3& into) {
    const tinygltf::Value& v = h.Get(key);
    if (!v.IsArray() || v.ArrayLen() != 3) return;
    for (int c = 0; c < 3; ++c)
      into[c] = finiteFactor(v.Get(c).GetNumberAsDouble(), fmt::format("{}: material '{}'", path, out.name), key);
  };
  rgb("reflectance", out.reflectance);
  rgb("emission", out.emission);
  for (int c = 0; c < 3; ++c)
    if (out.reflectance[c] < 0 || out.reflectance[c] > 1 || out.emission[c] < 0)
      fail("{}: material '{}': extras.hemirad reflectance or emission out of range", path, out.name);
}

glm::dmat4 localTransform(const tinygltf::Node& n, const std::string& path) {
  glm::dmat4 t(1.0);
  if (n.matrix.size() == 16) {
    for (int k = 0; k < 16; ++k) t[k / 4][k % 4] = finiteFactor(n.matrix[std::size_t(k)], path, "a node matrix");
    return t;
  }
  if (n.translation.size() == 3) t = glm::translate(t, {n.translation[0], n.translation[1], n.translation[2]});
  if (n.rotation.size() == 4)
    t *= glm::mat4_cast(glm::dquat(n.rotation[3], n.rotation[0], n.rotation[1], n.rotation[2]));
  if (n.scale.size() == 3) t = glm::scale(t, {n.scale[0], n.scale[1], n.scale[2]});
  for (int k = 0; k < 16; ++k) finiteFactor(t[k / 4][k % 4], path, "a node transform");
  return t;
}

// Joins the fan of triangles (a, b, c), (a, c, d), ... starting at triangle `first` into one
// polygon while it stays planar and convex; returns it and the triangles it used.
std::pair<Poly3, std::size_t> fanPolygon(const std::vector<glm::dvec3>& world, const std::vector<std::uint32_t>& idx,
                                         std::size_t first) {
  const std::size_t triangles = idx.size() / 3;
  Poly3 poly{world[idx[3 * first]], world[idx[3 * first + 1]], world[idx[3 * first + 2]]};
  std::size_t used = 1;
  while (first + used < triangles) {
    const std::uint32_t* t = &idx[3 * (first + used)];
    const std::uint32_t* prev = &idx[3 * (first + used - 1)];
    if (t[0] != idx[3 * first] || t[1] != prev[2]) break;
    Poly3 grown = poly;
    grown.push_back(world[t[2]]);
    if (!isPlanarConvex(grown)) break;
    poly = std::move(grown);
    ++used;
  }
  return {poly, used};
}

// Strip and fan indices as a triangle list (glTF 2.0, 3.7.2.1). Strip triangle i is (v_i, v_i+1,
// v_i+2) with the odd ones reversed, (v_i, v_i+2, v_i+1), so all keep the first one's winding;
// those repeating an index only stitch strips together and are dropped. Fan triangle i is (v_0,
// v_i+1, v_i+2), the spec's (v_i+1, v_i+2, v_0) rotated, which fanPolygon joins back into a polygon.
std::vector<std::uint32_t> triangleList(int mode, const std::vector<std::uint32_t>& idx) {
  if (mode != TINYGLTF_MODE_TRIANGLE_STRIP && mode != TINYGLTF_MODE_TRIANGLE_FAN) return idx;
  std::vector<std::uint32_t> out;
  for (std::size_t i = 0; i + 2 < idx.size(); ++i) {
    if (mode == TINYGLTF_MODE_TRIANGLE_FAN) {
      out.insert(out.end(), {idx[0], idx[i + 1], idx[i + 2]});
      continue;
    }
    const std::uint32_t a = idx[i], b = idx[i + 1 + i % 2], c = idx[i + 2 - i % 2];
    if (a != b && b != c && a != c) out.insert(out.end(), {a, b, c});
  }
  return out;
}

const char* modeName(int mode) {
  switch (mode) {
    case TINYGLTF_MODE_POINTS:
      return "points";
    case TINYGLTF_MODE_LINE:
      return "lines";
    case TINYGLTF_MODE_LINE_LOOP:
      return "a line loop";
    case TINYGLTF_MODE_LINE_STRIP:
      return "a line strip";
    default:
      return "an unknown mode";
  }
}

struct Loader {
  const tinygltf::Model& m;
  const std::string& path;
  Scene& scene;
  std::vector<int> materialIds;  // glTF material -> scene material
  int defaultMaterial = -1;
  std::size_t visited = 0;

  int material(int index) {
    if (index >= 0 && std::size_t(index) < materialIds.size()) return materialIds[std::size_t(index)];
    if (index >= 0) fail("{}: a primitive refers to material {} of {}", path, index, materialIds.size());
    if (defaultMaterial < 0) {
      defaultMaterial = scene.addMaterial({"(default)", glm::dvec3(0.5), glm::dvec3(0.0)});
      scene.warnings.push_back({path, "primitives without a material get reflectance 0.5", "scenes"});
    }
    return defaultMaterial;
  }

  void primitive(const tinygltf::Primitive& p, const glm::dmat4& world, int object, const std::string& where) {
    if (p.mode != -1 && (p.mode < TINYGLTF_MODE_TRIANGLES || p.mode > TINYGLTF_MODE_TRIANGLE_FAN)) {
      scene.warnings.push_back({where,
                                fmt::format("{} (mode {}) skipped: hemirad reads only surfaces (triangles, "
                                            "strips and fans)",
                                            modeName(p.mode), p.mode),
                                "primitives"});
      return;
    }
    auto pos = p.attributes.find("POSITION");
    if (pos == p.attributes.end()) fail("{}: a primitive has no POSITION", where);
    std::vector<glm::dvec3> points = positions(m, pos->second, path);
    for (auto& q : points) q = glm::dvec3(world * glm::dvec4(q, 1.0));
    const std::vector<std::uint32_t> idx = triangleList(p.mode, indices(m, p, points.size(), path));
    if (idx.size() % 3) fail("{}: {} indices are not whole triangles", where, idx.size());
    const int mat = material(p.material);
    const std::vector<glm::dvec2> uv = lightmapUvs(m, p, points.size(), path);
    for (std::size_t t = 0; t < idx.size() / 3;) {
      auto [poly, used] = fanPolygon(points, idx, t);
      const std::size_t first = scene.polygons().size();
      addFace(scene, poly, mat, object, [&] { return fmt::format("{} triangle {}", where, t); });
      if (!uv.empty()) recordUvs(scene, first, fanCorners(idx, t, used), points, uv);
      t += used;
    }
  }

  void camera(const tinygltf::Node& n, const glm::dmat4& world) {
    if (!scene.camera.empty() || n.camera < 0 || std::size_t(n.camera) >= m.cameras.size()) return;
    const tinygltf::Camera& c = m.cameras[std::size_t(n.camera)];
    if (c.type != "perspective" || !(c.perspective.yfov > 0) || !std::isfinite(c.perspective.yfov)) return;
    // glTF cameras look down their local -z with +y up.
    const glm::dvec3 eye(world * glm::dvec4(0, 0, 0, 1)), ahead(world * glm::dvec4(0, 0, -1, 0)),
        up(world * glm::dvec4(0, 1, 0, 0));
    const glm::dvec3 target = eye + ahead;
    scene.camera = fmt::format(
        "eye={:.17g},{:.17g},{:.17g} target={:.17g},{:.17g},{:.17g} up={:.17g},{:.17g},{:.17g} fov={:.17g}", eye.x,
        eye.y, eye.z, target.x, target.y, target.z, up.x, up.y, up.z, glm::degrees(c.perspective.yfov));
  }

  void node(int index, const glm::dmat4& parent, int depth) {
    if (index < 0 || std::size_t(index) >= m.nodes.size())
      fail("{}: node {} does not exist ({} nodes)", path, index, m.nodes.size());
    if (depth > 64 || ++visited > 100000) fail("{}: the node hierarchy is cyclic or too deep", path);
    const tinygltf::Node& n = m.nodes[std::size_t(index)];
    const glm::dmat4 world = parent * localTransform(n, path);
    camera(n, world);
    if (n.mesh >= 0) {
      if (std::size_t(n.mesh) >= m.meshes.size())
        fail("{}: node {} refers to mesh {} of {}", path, index, n.mesh, m.meshes.size());
      const tinygltf::Mesh& mesh = m.meshes[std::size_t(n.mesh)];
      const int object = scene.addObject(!n.name.empty()      ? n.name
                                         : !mesh.name.empty() ? mesh.name
                                                              : fmt::format("node {}", index));
      for (std::size_t p = 0; p < mesh.primitives.size(); ++p)
        primitive(mesh.primitives[p], world, object, fmt::format("{}: mesh {} primitive {}", path, n.mesh, p));
    }
    for (int child : n.children) node(child, world, depth + 1);
  }
};

}  // namespace

bool isGltfPath(const std::string& path) {
  const std::string ext = lower(std::filesystem::path(path).extension().string());
  return ext == ".gltf" || ext == ".glb";
}

Scene loadGltf(const std::string& path) {
  const tinygltf::Model model = readModel(path);
  Scene scene;
  scene.path = path;
  scene.emissionKey = "emissiveFactor";
  scene.sources = {{"the scene", path}};
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  auto external = [&](const std::string& uri) { return !uri.empty() && uri.rfind("data:", 0) != 0; };
  for (const tinygltf::Buffer& b : model.buffers)
    if (external(b.uri)) scene.sources.push_back({"a buffer the scene names", (folder / b.uri).string()});
  for (const tinygltf::Image& i : model.images)
    if (external(i.uri)) scene.sources.push_back({"an image the scene names", (folder / i.uri).string()});
  Loader loader{model, path, scene, {}};
  for (std::size_t k = 0; k < model.materials.size(); ++k) {
    Material material = toMaterial(model.materials[k], k, path, scene);
    applyHemiradExtras(model.materials[k], material, path);
    loader.materialIds.push_back(scene.addMaterial(material));
  }
  std::vector<int> roots;
  if (!model.scenes.empty()) {
    const std::size_t s = model.defaultScene >= 0 && std::size_t(model.defaultScene) < model.scenes.size()
                              ? std::size_t(model.defaultScene)
                              : 0;
    roots = model.scenes[s].nodes;
  } else {
    // No scene: every node that is no other node's child is a root.
    std::vector<bool> child(model.nodes.size(), false);
    for (const auto& n : model.nodes)
      for (int c : n.children)
        if (c >= 0 && std::size_t(c) < child.size()) child[std::size_t(c)] = true;
    for (std::size_t k = 0; k < model.nodes.size(); ++k)
      if (!child[k]) roots.push_back(int(k));
  }
  for (int root : roots) loader.node(root, glm::dmat4(1.0), 0);
  if (!scene.lightmapUv.empty()) scene.lightmapUv.resize(scene.polygons().size());
  return scene;
}

}  // namespace hemirad
