#include "src/scene/SceneLoader.h"

#include <tiny_obj_loader.h>

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <sstream>

#include "src/base/Error.h"
#include "src/scene/FaceRepair.h"
#include "src/scene/GltfLoader.h"
#include "src/scene/SceneFormat.h"
#include "src/scene/Units.h"

namespace hemirad {

namespace {

// Line numbers of OBJ statements, which tinyobjloader does not keep.
struct ObjLines {
  std::vector<int> faces;
  std::vector<std::pair<std::string, int>> usemtl, mtllib;
};

std::string trim(std::string s) {
  auto b = s.find_first_not_of(" \t\r"), e = s.find_last_not_of(" \t\r");
  return b == std::string::npos ? "" : s.substr(b, e - b + 1);
}

// Face indices, checked before tinyobjloader reads them with atoi: 0 and words would fail with a
// bare parse error, numbers beyond int wrap round into valid-looking indices. A positive index
// past the vertices so far may be a forward reference: it goes to `ahead`, checked at the end.
void checkFaceIndices(std::istringstream& ss, const std::string& path, int no, long long vertices,
                      std::vector<std::pair<int, long long>>& ahead) {
  std::string word;
  while (ss >> word) {
    size_t start = 0;
    for (int part = 0; start <= word.size(); ++part) {  // v, v/vt, v//vn, v/vt/vn
      size_t slash = word.find('/', start);
      std::string index = word.substr(start, slash == std::string::npos ? std::string::npos : slash - start);
      start = slash == std::string::npos ? word.size() + 1 : slash + 1;
      if (index.empty() && part > 0) continue;
      char* end = nullptr;
      errno = 0;
      long long i = std::strtoll(index.c_str(), &end, 10);
      if (index.empty() || end == index.c_str() || *end != '\0')
        fail("{}:{}: face index '{}' is not a number", path, no, index.empty() ? word : index);
      if (errno == ERANGE || i > INT32_MAX || i < INT32_MIN)
        fail("{}:{}: face index {} is out of range", path, no, index);
      if (i == 0) fail("{}:{}: face index 0 (OBJ indices start at 1)", path, no);
      if (part == 0 && i < 0 && -i > vertices)
        fail("{}:{}: relative vertex index {} reaches before the first vertex ({} so far)", path, no, i, vertices);
      if (part == 0 && i > vertices) ahead.emplace_back(no, i);
    }
  }
}

ObjLines scanLines(const std::string& path) {
  std::ifstream in(path);
  ObjLines lines;
  std::string line;
  long long vertices = 0;
  std::vector<std::pair<int, long long>> ahead;  // (line, vertex index) past the vertices before it
  for (int no = 1; std::getline(in, line); ++no) {
    std::istringstream ss(line);
    std::string key;
    ss >> key;
    if (key == "v") {
      // Coordinates must be finite numbers (tinyobjloader would read "nan" as 0).
      const char* p = line.c_str() + line.find('v') + 1;
      for (int i = 0; i < 3; ++i) {
        char* end = nullptr;
        errno = 0;
        double x = std::strtod(p, &end);
        if (end == p) fail("{}:{}: vertex needs three numbers", path, no);
        if (!std::isfinite(x)) fail("{}:{}: vertex coordinate is not a finite number", path, no);
        p = end;
      }
      ++vertices;
    } else if (key == "f") {
      lines.faces.push_back(no);
      checkFaceIndices(ss, path, no, vertices, ahead);
    } else if (key == "usemtl") {
      lines.usemtl.emplace_back(trim(line.substr(line.find("usemtl") + 6)), no);
    } else if (key == "mtllib") {
      lines.mtllib.emplace_back(trim(line.substr(line.find("mtllib") + 6)), no);
    }
  }
  for (auto [no, index] : ahead)
    if (index > vertices)
      fail("{}:{}: face refers to vertex {} but the file has {} vertices", path, no, index, vertices);
  return lines;
}

// Kd, Ka and Ke values must be finite numbers: tinyobjloader reads a word that is no number
// ("nan", "inf") as 0, so `Kd nan 0 0` would be a silent black material.
void scanMaterialNumbers(const std::string& objPath, const ObjLines& lines) {
  for (const auto& mtllib : lines.mtllib) {
    std::istringstream split(mtllib.first);
    std::string name, line;
    while (split >> name) {
      std::string mtlPath = (std::filesystem::path(objPath).parent_path() / name).string();
      std::ifstream in(mtlPath);
      for (int no = 1; std::getline(in, line); ++no) {
        std::istringstream ss(line);
        std::string key, word;
        ss >> key;
        if (key != "Kd" && key != "Ka" && key != "Ke") continue;
        for (int i = 0; i < 3 && ss >> word; ++i) {
          char* end = nullptr;
          double x = std::strtod(word.c_str(), &end);
          if (*end != '\0' || !std::isfinite(x))
            fail("{}:{}: {} value '{}' is not a finite number", name, no, key, word);
        }
      }
    }
  }
}

// Where each material's newmtl, Kd, Ka and Ke are ("FILE:LINE"), which tinyobjloader does not
// keep. Also refuses a material library that is there but is no readable file (a folder).
struct MtlLines {
  std::vector<InputPath> files;                                       // the MTLs and the texture maps they name
  std::map<std::string, std::vector<std::string>> newmtl;             // every definition of a name
  std::map<std::pair<std::string, std::string>, std::string> values;  // (name, key): its line
  std::set<std::pair<std::string, std::string>> grey;                 // (name, key) given one value: r = g = b
  std::vector<SceneWarning> warnings;                                 // texture maps, which are not used
  std::string fallback;
  std::string at(const std::string& name, const std::string& key) const {
    if (auto v = values.find({name, key}); v != values.end()) return v->second;
    // Kd before any newmtl makes an entry for "" with no definition (fuzzer crasher, tests/fuzz).
    if (auto d = newmtl.find(name); d != newmtl.end() && !d->second.empty()) return d->second.front();
    return fallback;
  }
};

MtlLines scanMaterialLines(const std::string& objPath, const ObjLines& lines) {
  namespace fs = std::filesystem;
  MtlLines out;
  out.fallback = lines.mtllib.empty() ? objPath : lines.mtllib.front().first;
  for (const auto& [names, mtllibLine] : lines.mtllib) {
    std::istringstream split(names);
    std::string name, line, current;
    while (split >> name) {
      fs::path mtlPath = fs::path(objPath).parent_path() / name;
      std::error_code ec;
      if (fs::exists(mtlPath, ec) && (!fs::is_regular_file(mtlPath, ec) || !std::ifstream(mtlPath)))
        fail("{}:{}: material library '{}' is not a readable file", objPath, mtllibLine, name);
      std::ifstream in(mtlPath);
      out.files.push_back({"the scene's material library", mtlPath.string()});
      for (int no = 1; std::getline(in, line); ++no) {
        std::istringstream ss(line);
        std::string key;
        ss >> key;
        std::string where = fmt::format("{}:{}", mtlPath.string(), no);
        if (key == "newmtl") out.newmtl[current = trim(line.substr(line.find("newmtl") + 6))].push_back(where);
        // A second definition of a name is refused before its values are read.
        if ((key == "Kd" || key == "Ka" || key == "Ke") && out.newmtl[current].size() == 1) {
          out.values[{current, key}] = where;
          // The MTL format's `Kd r [g b]`: one value is grey (tinyobjloader would read r 0 0).
          std::string value;
          int values = 0;
          while (ss >> value) ++values;
          if (values == 1) out.grey.insert({current, key});
        }
        if (key.rfind("map_", 0) == 0 || key == "bump" || key == "disp" || key == "decal") {
          std::string file, word;
          while (ss >> word) file = word;  // the map's options come first, its file last
          if (!file.empty())
            out.files.push_back({"a texture the scene names", (mtlPath.parent_path() / file).string()});
          const std::string ignored =
              "texture ignored: hemirad uses the constant Kd/Ke of each material, never textures";
          out.warnings.push_back(
              {where, fmt::format("material '{}': {} {}", current, key, ignored), "texture maps", ignored});
        }
      }
    }
  }
  return out;
}

bool finite3(const double* v) { return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]); }

Material toMaterial(const tinyobj::material_t& m, const LoadOptions& options, const MtlLines& mtl,
                    std::vector<SceneWarning>& warnings) {
  const double* e = options.emission == EmissionSource::Ka ? m.ambient : m.emission;
  Material out{m.name, {m.diffuse[0], m.diffuse[1], m.diffuse[2]}, {e[0], e[1], e[2]}};
  const char* eKey = options.emission == EmissionSource::Ka ? "Ka" : "Ke";
  if (mtl.grey.count({m.name, "Kd"})) out.reflectance = glm::dvec3(m.diffuse[0]);
  if (mtl.grey.count({m.name, eKey})) out.emission = glm::dvec3(e[0]);
  const std::string kd = mtl.at(m.name, "Kd"), ek = mtl.at(m.name, eKey);
  if (!finite3(m.diffuse)) fail("{}: material '{}': Kd is not a finite number", kd, m.name);
  if (!finite3(e)) fail("{}: material '{}': {} is not a finite number", ek, m.name, eKey);
  for (int c = 0; c < 3; ++c) {
    if (out.reflectance[c] > 1.0)
      fail("{}: material '{}': reflectance Kd {} is above 1 (it would reflect more light than it receives)", kd, m.name,
           out.reflectance[c]);
    if (out.reflectance[c] < 0.0)
      fail("{}: material '{}': reflectance Kd {} is negative", kd, m.name, out.reflectance[c]);
    if (out.emission[c] < 0.0) fail("{}: material '{}': emission {} {} is negative", ek, m.name, eKey, out.emission[c]);
  }
  // Exactly 1 (white paper in many models) is physical enough to solve: the light stays in play.
  if (glm::any(glm::equal(out.reflectance, glm::dvec3(1.0))))
    warnings.push_back({kd, fmt::format("material '{}': {}", m.name, kReflectanceOne), "materials", kReflectanceOne});
  return out;
}

// tinyobjloader's parse; a material library it cannot find is named with its mtllib line.
void readObj(tinyobj::ObjReader& reader, const std::string& path, const ObjLines& lines) {
  tinyobj::ObjReaderConfig config;
  config.triangulate = false;  // polygons keep their planarity
  config.vertex_color = false;
  if (!reader.ParseFromFile(path, config)) {
    std::string err = reader.Error();
    fail("{}: {}", path, trim(err.substr(0, err.find('\n'))));
  }
  const std::string& warning = reader.Warning();
  if (warning.find("Material file") != std::string::npos) {
    int line = lines.mtllib.empty() ? 0 : lines.mtllib.front().second;
    std::string name = lines.mtllib.empty() ? "" : lines.mtllib.front().first;
    fail("{}:{}: material library '{}' not found next to the OBJ", path, line, name);
  }
}

// The MTL's materials, each defined once, and every usemtl naming one of them.
void addMaterials(Scene& scene, const tinyobj::ObjReader& reader, const LoadOptions& options, const MtlLines& mtl,
                  const ObjLines& lines, const std::string& path) {
  std::map<std::string, int> materialIds;
  for (const auto& m : reader.GetMaterials()) {
    if (materialIds.count(m.name)) {
      auto d = mtl.newmtl.find(m.name);
      bool known = d != mtl.newmtl.end() && d->second.size() > 1;
      fail("{}: material '{}' is defined twice{}", known ? d->second[1] : mtl.fallback, m.name,
           known ? " (first at " + d->second[0] + ")" : "");
    }
    materialIds[m.name] = scene.addMaterial(toMaterial(m, options, mtl, scene.warnings));
  }
  for (const auto& [name, line] : lines.usemtl)
    if (!materialIds.count(name)) fail("{}:{}: unknown material '{}' (not in the MTL file)", path, line, name);
}

// A face's `n` vertices from `offset`, without consecutive repeats or a closing repeat.
Poly3 facePolygon(const tinyobj::attrib_t& attrib, const tinyobj::mesh_t& mesh, size_t offset, size_t n,
                  const FaceSite& where) {
  const size_t vertexCount = attrib.vertices.size() / 3;
  Poly3 poly;
  for (size_t k = 0; k < n; ++k) {
    int vi = mesh.indices[offset + k].vertex_index;
    if (vi < 0 || size_t(vi) >= vertexCount)
      fail("{}: face refers to vertex {} but the file has {} vertices", where(), vi + 1, vertexCount);
    glm::dvec3 p(attrib.vertices[3 * vi], attrib.vertices[3 * vi + 1], attrib.vertices[3 * vi + 2]);
    if (poly.empty() || p != poly.back()) poly.push_back(p);
  }
  while (poly.size() > 1 && poly.front() == poly.back()) poly.pop_back();
  return poly;
}

// A face's `n` vertices' positions and texture coordinates (OBJ `vt`), paired; empty when a
// vertex has none.
std::vector<std::pair<glm::dvec3, glm::dvec2>> faceUvs(const tinyobj::attrib_t& attrib, const tinyobj::mesh_t& mesh,
                                                       size_t offset, size_t n, const FaceSite& where) {
  const size_t uvCount = attrib.texcoords.size() / 2;
  std::vector<std::pair<glm::dvec3, glm::dvec2>> out;
  for (size_t k = 0; k < n; ++k) {
    const tinyobj::index_t i = mesh.indices[offset + k];
    if (i.texcoord_index < 0) return {};
    if (size_t(i.texcoord_index) >= uvCount)
      fail("{}: face refers to texture coordinate {} but the file has {}", where(), i.texcoord_index + 1, uvCount);
    const auto vi = size_t(i.vertex_index);  // checked by facePolygon
    out.push_back(
        {{attrib.vertices[3 * vi], attrib.vertices[3 * vi + 1], attrib.vertices[3 * vi + 2]},
         {attrib.texcoords[2 * size_t(i.texcoord_index)], attrib.texcoords[2 * size_t(i.texcoord_index) + 1]}});
  }
  return out;
}

// The OBJ's texture coordinates as lightmap UVs (--uv input) of the polygons addFace made from
// `first` on: each vertex's, matched by position (addFace keeps positions, or splits into its
// triangles), as the glTF loader's TEXCOORD_1.
void recordObjUvs(Scene& scene, std::size_t first, const std::vector<std::pair<glm::dvec3, glm::dvec2>>& corners) {
  scene.lightmapUv.resize(scene.polygons().size());
  for (std::size_t p = first; p < scene.polygons().size(); ++p) {
    Poly2 out;
    for (const glm::dvec3& x : scene.polygons()[p].vertices)
      for (const auto& [at, uv] : corners)
        if (at == x) {
          out.push_back(uv);
          break;
        }
    if (out.size() == scene.polygons()[p].vertices.size()) scene.lightmapUv[p] = std::move(out);
  }
}

}  // namespace

// The file as it is, in its own units.
static Scene readSceneFile(const std::string& path, const LoadOptions& options) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::exists(path, ec)) fail("{}: no such file", path);
  if (!fs::is_regular_file(path, ec)) fail("{}: is not a readable file (a folder?)", path);
  if (!std::ifstream(path)) fail("{}: cannot be read", path);
  if (sceneFormat(path) == SceneFormat::Gltf) return loadGltf(path);
  ObjLines lines = scanLines(path);
  if (lines.mtllib.empty() && !lines.usemtl.empty())
    fail("{}:{}: usemtl '{}' but the file names no material library (mtllib)", path, lines.usemtl.front().second,
         lines.usemtl.front().first);
  const MtlLines mtl = scanMaterialLines(path, lines);
  tinyobj::ObjReader reader;
  readObj(reader, path, lines);
  scanMaterialNumbers(path, lines);

  Scene scene;
  scene.path = path;
  scene.emissionKey = options.emission == EmissionSource::Ka ? "Ka" : "Ke";
  scene.warnings = mtl.warnings;
  scene.sources = mtl.files;
  scene.sources.insert(scene.sources.begin(), {"the scene", path});
  addMaterials(scene, reader, options, mtl, lines, path);
  int defaultMaterial = -1;
  size_t faceNo = 0, totalFaces = 0;
  for (const auto& shape : reader.GetShapes()) totalFaces += shape.mesh.num_face_vertices.size();
  const bool haveLines = totalFaces == lines.faces.size();
  const FaceSite where = [&] {
    return haveLines ? fmt::format("{}:{}", path, lines.faces[faceNo]) : fmt::format("{}: face {}", path, faceNo + 1);
  };
  for (const auto& shape : reader.GetShapes()) {
    int object = scene.addObject(shape.name.empty() ? "default" : shape.name);
    size_t offset = 0;
    for (size_t f = 0; f < shape.mesh.num_face_vertices.size(); ++f, ++faceNo) {
      const size_t n = shape.mesh.num_face_vertices[f];
      const Poly3 poly = facePolygon(reader.GetAttrib(), shape.mesh, offset, n, where);
      offset += n;
      int material = shape.mesh.material_ids[f];
      if (material < 0) {
        if (defaultMaterial < 0) {
          defaultMaterial = scene.addMaterial({"(default)", glm::dvec3(0.5), glm::dvec3(0.0)});
          scene.warnings.push_back({where(), "faces without a material get reflectance 0.5", "scenes"});
        }
        material = defaultMaterial;
      }
      const std::size_t first = scene.polygons().size();
      addFace(scene, poly, material, object, where);
      if (auto uv = faceUvs(reader.GetAttrib(), shape.mesh, offset - n, n, where); !uv.empty())
        recordObjUvs(scene, first, uv);
    }
  }
  if (!scene.lightmapUv.empty()) scene.lightmapUv.resize(scene.polygons().size());
  return scene;
}

Scene loadScene(const std::string& path, const LoadOptions& options) {
  Scene scene = readSceneFile(path, options);
  normalizeUnits(scene);
  return scene;
}

std::string noEmitterReason(const Scene& scene) {
  if (scene.emissionKey == "emissiveFactor")
    return "no material has a positive emissiveFactor (times KHR_materials_emissive_strength's emissiveStrength)";
  if (scene.emissionKey == "Ka")
    return "no material has a positive Ka (read for --emission ka; without it lights come from Ke)";
  return "no material has a positive Ke (use --emission ka if lights are given by Ka)";
}

void validateSolvable(const Scene& scene) {
  if (scene.polygons().empty()) fail("{}: the scene has no faces with area", scene.path);
  if (!(scene.emittedPower() > 0)) fail("{}: no emitter: {}", scene.path, noEmitterReason(scene));
}

}  // namespace hemirad
