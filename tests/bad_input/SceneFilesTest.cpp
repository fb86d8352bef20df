// Bad scene files (docs/errors.md): missing or unreadable OBJ and MTL files, broken face
// indices, non-finite coordinates, materials defined twice or unknown, no emitter, reflectance
// out of range: one error line naming the file and line, exit code 2, no output. Repairs
// (zero-area, non-planar faces) warn with the line and go on.
#include <algorithm>
#include <catch2/catch.hpp>
#include <cctype>
#include <cstdint>
#include <filesystem>

#include "src/scene/SceneLoader.h"
#include "tests/bad_input/BadInput.h"
#include "tests/support/Files.h"
#include "tests/support/Support.h"

using namespace hemirad;
using namespace hemirad::test::bad_input;
using Catch::Contains;
using hemirad::test::count;
namespace fs = std::filesystem;

// ---- files

TEST_CASE("Bad input: a missing OBJ file is one error naming the file", "[cli][bad-input]") {
  std::string missing = test::tempPath("no-such-scene.obj");
  expectRefused("missing-obj", solve(missing), {missing, "does not exist"});
}

TEST_CASE("Bad input: a folder given as the OBJ file is one error naming it", "[cli][bad-input]") {
  std::string dir = test::tempPath("folder.obj");
  fs::create_directories(dir);
  expectRefused("folder-obj", solve(dir), {dir, "directory"});
  CHECK_THROWS_WITH(loadScene(dir), Contains(dir + ": is not a readable file"));
}

TEST_CASE("Bad input: a folder given as the MTL file is one error naming the mtllib line", "[cli][bad-input]") {
  std::string obj = writeScene("folder-mtl", kQuad + "f 1 2 3 4\n");
  fs::remove(fs::path(obj).parent_path() / "m.mtl");
  fs::create_directories(fs::path(obj).parent_path() / "m.mtl");
  expectRefused("folder-mtl", solve(obj), {"s.obj:1: material library 'm.mtl' is not a readable file"});
}

TEST_CASE("Bad input: a missing MTL file is one error naming the mtllib line", "[cli][bad-input]") {
  std::string obj = writeScene("missing-mtl", "mtllib x.mtl\n" + kQuad.substr(13) + "f 1 2 3 4\n");
  expectRefused("missing-mtl", solve(obj), {"s.obj:1: material library 'x.mtl' not found"});
}

TEST_CASE("Bad input: an empty OBJ file is one error saying it has no faces", "[cli][bad-input]") {
  expectRefused("empty-obj", solve(writeScene("empty", "")), {"s.obj: the scene has no faces with area"});
  expectRefused("no-faces", solve(writeScene("no-faces", kQuad)), {"s.obj: the scene has no faces with area"});
  test::Run info = test::hemirad("info " + writeScene("empty-info", ""));
  INFO(info.output);
  CHECK(info.exitCode == 2);
  CHECK_THAT(info.output, Contains("s.obj: the scene has no faces with area"));
}

// ---- face indices

TEST_CASE("Bad input: a face indexing a vertex past the last one is one error naming its line", "[cli][bad-input]") {
  expectRefused("index-past-end", solve(writeScene("past-end", kQuad + "f 1 2 9\n")),
                {"s.obj:7: face refers to vertex 9 but the file has 4 vertices"});
}

TEST_CASE("Bad input: a negative face index reaching before the first vertex is one error naming its line",
          "[cli][bad-input]") {
  expectRefused("index-negative", solve(writeScene("negative", kQuad + "f -1 -2 -9\n")),
                {"s.obj:7: relative vertex index -9 reaches before the first vertex (4 so far)"});
}

TEST_CASE("Bad input: a zero face index is one error naming its line", "[cli][bad-input]") {
  expectRefused("index-zero", solve(writeScene("zero", kQuad + "f 0 1 2\n")),
                {"s.obj:7: face index 0 (OBJ indices start at 1)"});
}

TEST_CASE("Bad input: a face index beyond the int range is one error naming its line, never wrapped round",
          "[cli][bad-input]") {
  // 2^32 + 3 would wrap to 3 in tinyobjloader's atoi and load as a valid face.
  expectRefused("index-huge", solve(writeScene("huge", kQuad + "f 1 2 4294967299\n")),
                {"s.obj:7: face index 4294967299 is out of range"});
  expectRefused("index-int-min", solve(writeScene("int-min", kQuad + "f 1 2 -2147483648\n")),
                {"s.obj:7: relative vertex index -2147483648 reaches before the first vertex"});
}

TEST_CASE("Bad input: a face index that is not a number is one error naming its line", "[cli][bad-input]") {
  expectRefused("index-word", solve(writeScene("word", kQuad + "f 1 2 x\n")),
                {"s.obj:7: face index 'x' is not a number"});
}

// ---- coordinates and faces

TEST_CASE("Bad input: NaN and infinite vertex coordinates are one error naming their line", "[cli][bad-input]") {
  for (std::string bad : {"nan", "inf", "-inf", "1e999"}) {
    std::string obj = kQuad;
    obj.replace(obj.find("v 1 1 0"), 7, "v 1 " + bad + " 0");
    expectRefused("coordinate-" + bad, solve(writeScene("coordinate-" + bad, obj + "f 1 2 3 4\n")),
                  {"s.obj:4: vertex coordinate is not a finite number"});
  }
}

TEST_CASE("Bad input: zero-area faces are skipped with a warning naming their line and the solve goes on",
          "[cli][bad-input]") {
  std::string obj = writeScene("zero-area", kQuad + "v 2 0 0\nf 1 2 3 4\nf 1 2 5\nf 1 1 2\n");
  Outputs out("zero-area");
  test::Run run = test::hemirad(solve(obj) + " --report " + out.dir + "/r.json");
  INFO(run.output);
  CHECK(run.exitCode == 0);
  CHECK_THAT(run.output, Contains("hemirad: warning: " + obj + ":9: degenerate face with zero area skipped"));
  CHECK_THAT(run.output, Contains("hemirad: warning: " + obj + ":10: degenerate face with zero area skipped"));
  CHECK(count(run.output, "hemirad: error:") == 0);
  CHECK(fs::exists(out.dir + "/r.json"));
}

TEST_CASE("Bad input: a scene of zero-area faces only warns for each and is one error saying it has no faces",
          "[cli][bad-input]") {
  std::string obj = writeScene("all-zero-area", kQuad + "v 2 0 0\nf 1 2 5\nf 3 3 3\n");
  Outputs out("all-zero-area");
  test::Run run = test::hemirad(solve(obj) + out.flags);
  INFO(run.output);
  CHECK(run.exitCode == 2);
  CHECK(count(run.output, "hemirad: warning:") == 2);
  CHECK(count(run.output, "hemirad: error:") == 1);
  CHECK_THAT(run.output, Contains("s.obj: the scene has no faces with area"));
  CHECK(out.empty());
}

TEST_CASE(
    "Bad input: a non-planar polygon is split into triangles with a warning naming its line and the solve goes on",
    "[cli][bad-input]") {
  std::string obj = kQuad;
  obj.replace(obj.find("v 1 1 0"), 7, "v 1 1 0.5");
  obj = writeScene("non-planar", obj + "f 1 2 3 4\n");
  Outputs out("non-planar");
  test::Run run = test::hemirad(solve(obj) + " --report " + out.dir + "/r.json");
  INFO(run.output);
  CHECK(run.exitCode == 0);
  CHECK_THAT(run.output, Contains("hemirad: warning: " + obj + ":7: non-planar polygon split into triangles"));
  CHECK(fs::exists(out.dir + "/r.json"));
}

TEST_CASE(
    "A face repeating its vertex cycle is read once with one warning: the single cycle's area, and a solve's "
    "convergence never goes negative",
    "[cli][bad-input]") {
  // A triangle given twice reads as the triangle.
  const Scene triangle = loadScene(writeScene("cycle-triangle", kQuad + "f 1 2 3\n"));
  const Scene twice = loadScene(writeScene("cycle-triangle-twice", kQuad + "f 1 2 3 1 2 3\n"));
  CHECK(twice.totalArea() == Approx(triangle.totalArea()).epsilon(1e-12));
  CHECK(twice.warnings.size() == 1);

  // The Cornell box with the cycles of its floor and three walls given three times: read as they
  // were, these big receivers counted their area thrice, and the solve created energy.
  const std::string cornell = test::readText(test::sourcePath("scenes/cornell/cornell.obj"));
  std::string repeated = cornell;
  for (std::string face : {"f 1 2 3 4", "f 25 26 27 28", "f 29 30 31 32", "f 33 34 35 36"}) {
    const std::string cycle = face.substr(1);
    repeated.replace(repeated.find(face + "\n"), face.size(), face + cycle + cycle);
  }
  const std::string mtl = test::readText(test::sourcePath("scenes/cornell/cornell.mtl"));
  const std::string once = test::writeScene("cycle-once", cornell, mtl, "s.obj", "cornell.mtl");
  const std::string thrice = test::writeScene("cycle-thrice", repeated, mtl, "s.obj", "cornell.mtl");
  const Scene a = loadScene(once), b = loadScene(thrice);
  CHECK(b.polygons().size() == a.polygons().size());
  CHECK(b.totalArea() == Approx(a.totalArea()).epsilon(1e-12));
  CHECK(b.warnings.size() == 4);
  if (!b.warnings.empty())
    CHECK_THAT(b.warnings[0].text(), Contains("s.obj:10: face repeats its vertex cycle; read as the single cycle"));

  auto convergence = [](const std::string& obj) {
    const std::string report = fs::path(obj).parent_path().string() + "/r.json";
    test::Run run = test::hemirad("solve " + obj + " --elements 600 --shots 150 --quiet --report " + report);
    INFO(run.output);
    REQUIRE(run.exitCode == 0);
    const nlohmann::json r = test::readJson(report);
    std::vector<double> h;  // [shots, convergence] where each pass began
    for (const auto& entry : r["convergence_history"]) h.push_back(entry[1].get<double>());
    return h;
  };
  const std::vector<double> history = convergence(thrice);
  REQUIRE(!history.empty());
  CHECK(*std::min_element(history.begin(), history.end()) >= 0);
  CHECK(history == convergence(once));  // the repaired scene is the box itself
}

TEST_CASE("Many warnings of one kind are one line: a scene of non-planar faces prints their count and first lines",
          "[cli][bad-input]") {
  // Lines 1-6 are kQuad; each bent quad is then four vertices and a face.
  const int faces = 40;
  std::string obj = kQuad;
  std::vector<int> faceLines;
  for (int k = 0; k < faces; ++k) {
    obj += fmt::format("v {0} 0 0\nv {1} 0 0\nv {1} 1 0.5\nv {0} 1 0\nf -4 -3 -2 -1\n", 2 * k, 2 * k + 1);
    faceLines.push_back(6 + 5 * (k + 1));
  }
  const std::string path = writeScene("many-non-planar", obj);
  std::string expected = fmt::format("{} faces: non-planar polygon split into triangles (first at", faces);
  for (std::size_t k = 0; k < kWarningPlaces; ++k)
    expected += fmt::format("{} {}:{}", k ? "," : "", path, faceLines[k]);
  expected += ", ...)";

  Outputs out("many-non-planar");
  test::Run run = test::hemirad(solve(path) + " --report " + out.dir + "/r.json");
  INFO(run.output);
  CHECK(run.exitCode == 0);
  CHECK(count(run.output, "hemirad: warning:") == 1);
  CHECK_THAT(run.output, Contains("hemirad: warning: " + expected + "\n"));
  test::Run info = test::hemirad("info " + path);
  INFO(info.output);
  CHECK(info.exitCode == 0);
  CHECK_THAT(info.output, Contains(fmt::format("warnings     {}\n  {}\n", faces, expected)));
}

// ---- materials

TEST_CASE("Bad input: a material defined twice is one error naming the MTL file and line", "[cli][bad-input]") {
  std::string obj = writeScene("duplicate", kQuad + "f 1 2 3 4\n", kMtl + "newmtl lamp\nKe 2 2 2\n");
  expectRefused("duplicate", solve(obj), {"m.mtl:6: material 'lamp' is defined twice"});
}

TEST_CASE("Bad input: an unknown material is one error naming the usemtl line", "[cli][bad-input]") {
  std::string obj = writeScene("unknown", kQuad + "usemtl neon\nf 1 2 3 4\n");
  expectRefused("unknown", solve(obj), {"s.obj:7: unknown material 'neon' (not in the MTL file)"});
}

TEST_CASE("Bad input: a scene without emitters is one error saying so", "[cli][bad-input]") {
  std::string obj = writeScene("dark", "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nusemtl grey\nf 1 2 3\n");
  expectRefused("dark", solve(obj), {"s.obj: no emitter"});
}

TEST_CASE(
    "Reflectance exactly 1 (Kd 1) is solved with one warning naming the material, and converges in an open "
    "scene",
    "[cli][bad-input]") {
  // The lamp quad at z = 0 facing +z, a white quad at z = 1 facing it.
  const std::string obj = writeScene("rho-one",
                                     kQuad +
                                         "f 1 2 3 4\nv 0 0 1\nv 0 1 1\nv 1 1 1\nv 1 0 1\nusemtl white\n"
                                         "f 5 6 7 8\n",
                                     kMtl + "newmtl white\nKd 1 1 1\n");
  const Scene scene = loadScene(obj);
  CHECK(scene.materials.back().reflectance == glm::dvec3(1.0));
  Outputs out("rho-one");
  const std::string report = out.dir + "/r.json";
  test::Run run = test::hemirad("solve " + obj + " --elements 500 --converge 0.99 --quiet --report " + report);
  INFO(run.output);
  CHECK(run.exitCode == 0);
  CHECK(count(run.output, "hemirad: warning:") == 1);
  CHECK_THAT(run.output, Contains("m.mtl:7: material 'white': " + std::string(kReflectanceOne)));
  const double convergence = test::readJson(report)["convergence"].get<double>();
  CHECK(convergence >= 0.99);
  CHECK(convergence <= 1.0);
}

TEST_CASE("Bad input: reflectance above 1 or below 0 is one error naming the MTL file and line", "[cli][bad-input]") {
  std::string high = writeScene("rho-high", kQuad + "f 1 2 3 4\n", "newmtl lamp\nKe 1 1 1\nKd 0.5 1.001 0.5\n");
  expectRefused("rho-high", solve(high), {"m.mtl:3: material 'lamp': reflectance Kd 1.001 is above 1"});
  std::string low = writeScene("rho-low", kQuad + "f 1 2 3 4\n", "newmtl lamp\nKe 1 1 1\nKd 0.5 -0.1 0.5\n");
  expectRefused("rho-low", solve(low), {"m.mtl:3: material 'lamp': reflectance Kd -0.1 is negative"});
}

TEST_CASE("Bad input: usemtl in an OBJ naming no material library is one error naming the usemtl line",
          "[cli][bad-input]") {
  // kQuad without its mtllib line: usemtl moves to line 5.
  const std::string obj = writeScene("usemtl-no-mtllib", kQuad.substr(kQuad.find('\n') + 1) + "f 1 2 3 4\n");
  expectRefused("usemtl-no-mtllib", solve(obj),
                {"s.obj:5: usemtl 'lamp' but the file names no material library (mtllib)"});
}

// ---- other formats and encodings

TEST_CASE("Bad input: a scene file of another 3D format is one error naming the formats hemirad reads",
          "[cli][bad-input]") {
  for (std::string ext : {"ply", "fbx", "dae", "3ds", "stl", "FBX", "blend", "usdz"}) {
    const std::string path = test::writeTempFile("format." + ext, "solid nothing\n");
    std::string lower = ext;
    for (char& c : lower) c = char(std::tolower(static_cast<unsigned char>(c)));
    expectRefused("format-" + ext, solve(path),
                  {path + ": unsupported format ." + lower + ": hemirad reads OBJ (+MTL) and glTF 2.0 (.gltf, .glb)"});
  }
  const std::string mtl = fs::path(writeScene("mtl-as-scene", kQuad + "f 1 2 3 4\n")).parent_path().string() + "/m.mtl";
  expectRefused("mtl-as-scene", solve(mtl), {mtl + ": is a material library (MTL); give the OBJ that names it"});
}

namespace {
// `text` (ASCII) as UTF-16, little- or big-endian, with or without its byte order mark.
std::string utf16(const std::string& text, bool little, bool bom) {
  std::string out = bom ? (little ? "\xFF\xFE" : "\xFE\xFF") : "";
  for (char c : text) out += little ? std::string{c, '\0'} : std::string{'\0', c};
  return out;
}
}  // namespace

TEST_CASE("Bad input: a UTF-16 OBJ is one error saying to save it as UTF-8 or ASCII", "[cli][bad-input]") {
  for (auto [little, bom] : {std::pair{true, true}, std::pair{false, true}, std::pair{true, false}}) {
    const std::string name = fmt::format("utf16-{}-{}", little ? "le" : "be", bom ? "bom" : "plain");
    const std::string obj = writeScene(name, utf16(kQuad + "f 1 2 3 4\n", little, bom));
    expectRefused(name, solve(obj), {obj + " is UTF-16 text; save it as UTF-8 or ASCII"});
  }
}

TEST_CASE("Bad input: a glTF 1.0 file (.gltf or .glb) is one error saying to convert it to glTF 2.0",
          "[cli][bad-input]") {
  const std::string message = ": glTF 1.0 is not supported; convert it to glTF 2.0";
  // glTF 1.0 keeps its objects in dictionaries keyed by id, and may leave out asset.
  const std::string meshes = R"("meshes":{"quad":{"primitives":[{"attributes":{"POSITION":"pos"},"mode":4}]}})";
  const std::string versioned = test::writeTempFile("gltf1.gltf", R"({"asset":{"version":"1.0"},)" + meshes + "}");
  expectRefused("gltf1", solve(versioned), {versioned + message});
  const std::string bare = test::writeTempFile("gltf1-bare.gltf", "{" + meshes + R"(,"scene":"defaultScene"})");
  expectRefused("gltf1-bare", solve(bare), {bare + message});
  // A 1.0 binary (KHR_binary_glTF): magic, version 1, length, then its JSON.
  const std::string json = R"({"asset":{"version":"1.0"}})";
  std::string glb = "glTF";
  for (std::uint32_t word : {1u, std::uint32_t(20 + json.size()), std::uint32_t(json.size()), 0u})
    glb.append(reinterpret_cast<const char*>(&word), 4);
  const std::string binary = test::writeTempFile("gltf1.glb", glb + json);
  expectRefused("gltf1-glb", solve(binary), {binary + message});
}

// ---- no emitter

TEST_CASE(
    "Bad input: the no-emitter error names glTF's emissiveFactor for glTF, and never suggests --emission ka "
    "when it was given",
    "[cli][bad-input]") {
  // The glTF Cornell box with its light made dark: its emissiveFactor (and the comma after it) removed.
  std::string text = test::readText(test::sourcePath("scenes/cornell/cornell.gltf"));
  const std::size_t at = text.find("\"emissiveFactor\"");
  REQUIRE(at != std::string::npos);
  text.erase(at, text.find(']', at) + 2 - at);
  const std::string gltf = test::writeTempFile("dark.gltf", text);
  expectRefused("dark-gltf", solve(gltf),
                {gltf + ": no emitter: no material has a positive emissiveFactor (times "
                        "KHR_materials_emissive_strength"});
  test::Run glRun = test::hemirad(solve(gltf));
  CHECK_THAT(glRun.output, !Contains("--emission ka") && !Contains("positive Ke"));

  const std::string obj = writeScene("dark-ka", kQuad + "usemtl grey\nf 1 2 3 4\n");
  const std::string ka = solve(obj) + " --emission ka";
  expectRefused("dark-ka", ka, {obj + ": no emitter: no material has a positive Ka"});
  test::Run kaRun = test::hemirad(ka);
  CHECK_THAT(kaRun.output, !Contains("use --emission ka"));
  expectRefused("dark-ke", solve(obj), {obj + ": no emitter: no material has a positive Ke (use --emission ka"});
}
