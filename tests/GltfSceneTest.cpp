// glTF 2.0 scenes load into the same Scene as OBJ+MTL (src/scene/GltfLoader.h): the Cornell box
// written as glTF (scenes/tools/obj_to_gltf.py) is the OBJ's scene and solves to its radiosity;
// node transforms, emissive strength and cameras are applied; bad glTF is one error line. Also
// the MTL's one-value `Kd` (grey) and its texture maps (a warning).
#include <tiny_gltf.h>

#include <catch2/catch.hpp>
#include <cstdint>
#include <filesystem>
#include <fstream>

#include "src/base/Error.h"
#include "src/scene/Camera.h"
#include "src/scene/SceneLoader.h"
#include "tests/bad_input/BadInput.h"
#include "tests/support/Files.h"
#include "tests/support/Support.h"

using namespace hemirad;
using Catch::Contains;
namespace fs = std::filesystem;

namespace {
// A unit quad in z = 0 as fan triangles (0 1 2, 0 2 3): 4 float VEC3 positions, 6 uint indices.
const std::string kQuadBuffer =
    "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAACAPwAAgD8AAAAAAAAAAAAAgD8AAAAAAAAAAAEAAAAC"
    "AAAAAAAAAAIAAAADAAAA";

// A glTF with the quad as mesh 0 (material 0) and the given nodes, scene nodes and materials.
std::string gltf(const std::string& nodes, const std::string& sceneNodes, const std::string& materials,
                 const std::string& extra = "", const std::string& indexCount = "6") {
  return R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[)" + sceneNodes + R"(]}],"nodes":[)" + nodes +
         R"(],"meshes":[{"name":"quad","primitives":[{"attributes":{"POSITION":0},"indices":1,"material":0}]}],)" +
         R"("materials":[)" + materials +
         R"(],"accessors":[{"bufferView":0,"componentType":5126,"count":4,"type":"VEC3"},)" +
         R"({"bufferView":1,"componentType":5125,"count":)" + indexCount + R"(,"type":"SCALAR"}],)" +
         R"("bufferViews":[{"buffer":0,"byteOffset":0,"byteLength":48},{"buffer":0,"byteOffset":48,"byteLength":24}],)" +
         R"("buffers":[{"byteLength":72,"uri":")" + kQuadBuffer + "\"}]" + extra + "}";
}

const std::string kLamp =
    R"({"name":"lamp","pbrMetallicRoughness":{"baseColorFactor":[0.5,0.5,0.5,1]},"emissiveFactor":[1,0.5,0.25],)"
    R"("extensions":{"KHR_materials_emissive_strength":{"emissiveStrength":8}}})";

std::string writeGltf(const std::string& name, const std::string& text) {
  return test::writeTempFile(name + ".gltf", text);
}
}  // namespace

TEST_CASE("The glTF Cornell box loads to the OBJ's scene: polygons, areas, materials, objects, emitted power",
          "[cpu]") {
  const Scene obj = loadScene(test::sourcePath("scenes/cornell/cornell.obj"));
  const Scene gl = loadScene(test::sourcePath("scenes/cornell/cornell.gltf"));
  CHECK(gl.warnings.empty());
  REQUIRE(gl.polygons().size() == obj.polygons().size());  // fan triangles joined back into the quads
  for (std::size_t p = 0; p < obj.polygons().size(); ++p) {
    const ScenePolygon &a = obj.polygons()[p], &b = gl.polygons()[p];
    INFO("polygon " << p);
    CHECK(b.vertices.size() == a.vertices.size());
    CHECK(b.area == Approx(a.area).epsilon(1e-6));  // float positions in the glTF buffer
    CHECK(glm::length(b.normal - a.normal) < 1e-6);
    CHECK(gl.materials[std::size_t(b.material)].name == obj.materials[std::size_t(a.material)].name);
    CHECK(gl.objects[std::size_t(b.object)].name == obj.objects[std::size_t(a.object)].name);
  }
  for (std::size_t m = 0; m < obj.materials.size(); ++m) {
    CHECK(glm::length(gl.materials[m].reflectance - obj.materials[m].reflectance) < 1e-12);
    CHECK(glm::length(gl.materials[m].emission - obj.materials[m].emission) < 1e-12);  // 17 x (1, 12/17, 4/17)
  }
  CHECK(gl.totalArea() == Approx(obj.totalArea()).epsilon(1e-6));
  CHECK(gl.emittedPower() == Approx(obj.emittedPower()).epsilon(1e-6));
}

TEST_CASE("A glTF scene's first perspective camera is its camera, which --camera and SCENE.camera still override",
          "[cpu]") {
  // Alone in a folder, so no cornell.camera sidecar applies: the camera must come from the file.
  const std::string dir = test::tempPath("gltf-camera");
  fs::create_directories(dir);
  fs::copy_file(test::sourcePath("scenes/cornell/cornell.gltf"), dir + "/box.gltf");
  const Scene scene = loadScene(dir + "/box.gltf");
  const Camera c = resolveCamera(scene, std::nullopt);
  CHECK(glm::length(c.eye - glm::dvec3(278, 273, -800)) < 1e-9);
  CHECK(glm::length(glm::normalize(c.target - c.eye) - glm::dvec3(0, 0, 1)) < 1e-12);
  CHECK(glm::length(c.up - glm::dvec3(0, 1, 0)) < 1e-12);
  CHECK(c.fovY == Approx(39.3).epsilon(1e-12));
  CHECK(resolveCamera(scene, std::string("fov=20")).fovY == 20);
  CHECK(resolveCamera(scene, std::string("fov=20")).eye == c.eye);
}

TEST_CASE("glTF node transforms (TRS and matrix, nested) place meshes and emissiveFactor x strength is E", "[cpu]") {
  // Node 0: translate (10, 0, 0), scale 2, rotate 90 degrees about z; its child node 1 adds a
  // matrix translating by (0, 0, 5). Node 2: the quad untransformed.
  const std::string nodes =
      R"({"name":"outer","mesh":0,"translation":[10,0,0],"rotation":[0,0,0.7071067811865476,0.7071067811865476],)"
      R"("scale":[2,2,2],"children":[1]},{"name":"inner","mesh":0,"matrix":[1,0,0,0,0,1,0,0,0,0,1,0,0,0,5,1]},)"
      R"({"name":"plain","mesh":0})";
  const Scene s = loadScene(writeGltf("transforms", gltf(nodes, "0,2", kLamp)));
  REQUIRE(s.polygons().size() == 3);
  const auto& outer = s.polygons()[0].vertices;
  REQUIRE(outer.size() == 4);
  // (1, 0, 0) -> scale (2, 0, 0) -> rotate (0, 2, 0) -> translate (10, 2, 0).
  CHECK(glm::length(outer[1] - glm::dvec3(10, 2, 0)) < 1e-9);
  CHECK(s.polygons()[0].area == Approx(4.0));
  // inner: parent x (0, 0, 5): z = 2 x 5 = 10 after the parent's scale.
  CHECK(glm::length(s.polygons()[1].vertices[1] - glm::dvec3(10, 2, 10)) < 1e-9);
  CHECK(s.polygons()[2].area == Approx(1.0));
  CHECK(s.objects.size() == 3);
  CHECK(glm::length(s.materials[0].emission - glm::dvec3(8, 4, 2)) < 1e-12);
  CHECK(glm::length(s.materials[0].reflectance - glm::dvec3(0.5)) < 1e-12);
}

TEST_CASE("The glTF Cornell box solves to the OBJ's radiosity", "[heavy][cli]") {
  auto report = [](const std::string& scene) {
    const std::string path = test::tempPath("gltf-vs-obj-" + fs::path(scene).extension().string().substr(1) + ".json");
    test::Run run =
        test::hemirad("solve " + test::sourcePath(scene) + " --elements 600 --shots 48 --quiet --report " + path);
    INFO(run.output);
    REQUIRE(run.exitCode == 0);
    return test::readJson(path);
  };
  const nlohmann::json obj = report("scenes/cornell/cornell.obj"), gl = report("scenes/cornell/cornell.gltf");
  CHECK(gl["elements"] == obj["elements"]);
  CHECK(gl["shots"] == obj["shots"]);
  CHECK(gl["convergence"].get<double>() == Approx(obj["convergence"].get<double>()).epsilon(1e-5));
  REQUIRE(gl["objects"].size() == obj["objects"].size());
  for (std::size_t k = 0; k < obj["objects"].size(); ++k)
    for (int c = 0; c < 3; ++c)
      CHECK(gl["objects"][k]["mean_radiosity"][c].get<double>() ==
            Approx(obj["objects"][k]["mean_radiosity"][c].get<double>()).epsilon(1e-4));
}

TEST_CASE("MTL: one Kd value is grey and texture maps are ignored with a warning naming the line", "[cpu]") {
  const std::string obj =
      test::writeScene("kd-grey", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nusemtl a\nf 1 2 3 4\n",
                       "newmtl a\nKd 0.4\nKe 2\nmap_Kd wood.png\n");
  const Scene s = loadScene(obj);
  CHECK(s.materials[0].reflectance == glm::dvec3(0.4));
  CHECK(s.materials[0].emission == glm::dvec3(2.0));
  REQUIRE(s.warnings.size() == 1);
  CHECK_THAT(s.warnings[0].text(), Contains("m.mtl:4: material 'a': map_Kd texture ignored"));
}

TEST_CASE("Bad input: broken glTF is one error line naming the file and what is wrong", "[cli][bad-input]") {
  using test::bad_input::expectRefused;
  auto scene = [](const std::string& name, const std::string& text) { return writeGltf("bad-" + name, text); };
  expectRefused("gltf-json", "solve " + scene("json", "{\"asset\":") + " --shots 2 --quiet", {"bad-json.gltf:"});
  expectRefused("gltf-past-buffer",
                "solve " + scene("past", gltf(R"({"mesh":0})", "0", kLamp, "", "60")) + " --shots 2 --quiet",
                {"bad-past.gltf: indices: accessor 1 reaches past the end of its buffer"});
  expectRefused(
      "gltf-bright",
      "solve " +
          scene("bright",
                gltf(R"({"mesh":0})", "0",
                     R"({"pbrMetallicRoughness":{"baseColorFactor":[1,1.25,1,1]},"emissiveFactor":[1,1,1]})")) +
          " --shots 2 --quiet",
      {"material 'material 0': reflectance baseColorFactor 1.25 is above 1"});
  expectRefused(
      "gltf-dark",
      "solve " +
          scene("dark", gltf(R"({"mesh":0})", "0", R"({"pbrMetallicRoughness":{"baseColorFactor":[0.5,0.5,0.5,1]}})")) +
          " --shots 2 --quiet",
      {"no emitter"});
  expectRefused("gltf-node",
                "solve " + scene("node", gltf(R"({"mesh":0,"children":[7]})", "0", kLamp)) + " --shots 2 --quiet",
                {"bad-node.gltf: node 7 does not exist (1 nodes)"});
}

TEST_CASE("A glTF material without baseColorFactor (reflectance 1) loads with one warning naming it", "[cpu]") {
  const std::string paper = R"({"name":"paper","emissiveFactor":[1,1,1]})";
  const Scene s = loadScene(writeGltf("rho-one", gltf(R"({"mesh":0})", "0", paper)));
  REQUIRE(s.materials.size() == 1);
  CHECK(s.materials[0].reflectance == glm::dvec3(1.0));  // glTF's default baseColorFactor
  REQUIRE(s.warnings.size() == 1);
  CHECK_THAT(s.warnings[0].text(), Contains("material 'paper': " + std::string(kReflectanceOne)));
}

namespace {
// Appends `values` to buffer 0 as a buffer view and an accessor of `count` elements; returns the accessor.
template <class T>
int addAccessor(tinygltf::Model& m, const std::vector<T>& values, int componentType, int type, std::size_t count) {
  if (m.buffers.empty()) m.buffers.emplace_back();
  std::vector<unsigned char>& data = m.buffers[0].data;
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = data.size();
  view.byteLength = values.size() * sizeof(T);
  const auto* bytes = reinterpret_cast<const unsigned char*>(values.data());
  data.insert(data.end(), bytes, bytes + view.byteLength);
  while (data.size() % 4) data.push_back(0);
  m.bufferViews.push_back(view);
  tinygltf::Accessor a;
  a.bufferView = int(m.bufferViews.size()) - 1;
  a.componentType = componentType;
  a.type = type;
  a.count = count;
  m.accessors.push_back(a);
  return int(m.accessors.size()) - 1;
}

// A primitive of `mode` over `points`, indexed by `indices` when there are any.
void addPrimitive(tinygltf::Model& m, int mode, const std::vector<glm::vec3>& points,
                  const std::vector<std::uint16_t>& indices) {
  tinygltf::Primitive p;
  p.mode = mode;
  p.material = 0;
  p.attributes["POSITION"] = addAccessor(m, points, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, points.size());
  if (!indices.empty())
    p.indices = addAccessor(m, indices, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_SCALAR, indices.size());
  m.meshes[0].primitives.push_back(p);
}

// The triangles of a strip or fan as the glTF 2.0 spec (3.7.2.1) defines them, zero-area ones left out.
std::vector<Poly3> specTriangles(int mode, const std::vector<glm::vec3>& points, std::vector<std::uint16_t> indices) {
  if (indices.empty())
    for (std::size_t k = 0; k < points.size(); ++k) indices.push_back(std::uint16_t(k));
  std::vector<Poly3> out;
  for (std::size_t i = 0; i + 2 < indices.size(); ++i) {
    const std::size_t a = mode == TINYGLTF_MODE_TRIANGLE_FAN ? i + 1 : i;
    const std::size_t b = mode == TINYGLTF_MODE_TRIANGLE_FAN ? i + 2 : i + 1 + i % 2;
    const std::size_t c = mode == TINYGLTF_MODE_TRIANGLE_FAN ? 0 : i + 2 - i % 2;
    Poly3 t{glm::dvec3(points[indices[a]]), glm::dvec3(points[indices[b]]), glm::dvec3(points[indices[c]])};
    if (area(t) > 0) out.push_back(t);
  }
  return out;
}
}  // namespace

TEST_CASE(
    "glTF triangle strips and fans, indexed or not, load as their triangles with the spec's winding, and points and "
    "lines are skipped with a warning",
    "[cpu]") {
  tinygltf::Model m;
  m.asset.version = "2.0";
  m.meshes.emplace_back();
  tinygltf::Material lamp;
  lamp.emissiveFactor = {1, 1, 1};
  lamp.pbrMetallicRoughness.baseColorFactor = {0.5, 0.5, 0.5, 1};
  m.materials.push_back(lamp);
  // A planar strip of 4 triangles; two quads stitched into one strip by repeated indices; a fan
  // round a pyramid's apex (non-planar, so its triangles stay triangles), plain and indexed.
  std::vector<glm::vec3> strip, quads, pyramid{{0, 0, 1}, {-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, {-1, -1, 0}};
  for (int k = 0; k < 3; ++k) strip.insert(strip.end(), {{k, 0, 0}, {k, 1, 0}});
  for (float x : {3.f, 5.f}) quads.insert(quads.end(), {{x, 0, 0}, {x + 1, 0, 0}, {x, 1, 0}, {x + 1, 1, 0}});
  const std::vector<std::uint16_t> stitched{0, 1, 2, 3, 3, 4, 4, 5, 6, 7}, ring{0, 5, 4, 3, 2, 1};
  const struct {
    int mode;
    const std::vector<glm::vec3>& points;
    std::vector<std::uint16_t> indices;
  } prims[] = {{TINYGLTF_MODE_TRIANGLE_STRIP, strip, {}},
               {TINYGLTF_MODE_TRIANGLE_STRIP, quads, stitched},
               {TINYGLTF_MODE_TRIANGLE_FAN, pyramid, {}},
               {TINYGLTF_MODE_TRIANGLE_FAN, pyramid, ring}};
  std::vector<Poly3> expected;
  for (const auto& p : prims) {
    addPrimitive(m, p.mode, p.points, p.indices);
    for (const Poly3& t : specTriangles(p.mode, p.points, p.indices)) expected.push_back(t);
  }
  addPrimitive(m, TINYGLTF_MODE_POINTS, strip, {});
  addPrimitive(m, TINYGLTF_MODE_LINE, strip, {});
  tinygltf::Node node;
  node.mesh = 0;
  m.nodes.push_back(node);
  m.scenes.emplace_back().nodes = {0};
  m.defaultScene = 0;
  const std::string path = test::tempPath("strips-fans.gltf");
  REQUIRE(tinygltf::TinyGLTF().WriteGltfSceneToFile(&m, path, false, true, true, false));

  const Scene s = loadScene(path);
  REQUIRE(s.polygons().size() == expected.size());
  double expectedArea = 0;
  for (std::size_t k = 0; k < expected.size(); ++k) {
    INFO("triangle " << k);
    const ScenePolygon& p = s.polygons()[k];
    expectedArea += area(expected[k]);
    CHECK(p.area == Approx(area(expected[k])).epsilon(1e-6));
    CHECK(glm::dot(p.normal, glm::normalize(newellNormal(expected[k]))) > 1 - 1e-9);  // the same winding
  }
  CHECK(s.totalArea() == Approx(expectedArea).epsilon(1e-9));
  REQUIRE(s.warnings.size() == 2);
  CHECK_THAT(s.warnings[0].text(), Contains("mesh 0 primitive 4: points (mode 0) skipped"));
  CHECK_THAT(s.warnings[1].text(), Contains("mesh 0 primitive 5: lines (mode 1) skipped"));
}
