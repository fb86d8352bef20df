// Issue 7's table of bad inputs (README, "Bad input"), one TEST_CASE per row: each bad input
// gives exactly one `hemirad: error:` line naming the file and line (scene content) or the flag,
// exit code 2, and leaves nothing in the output folder. Repairs (zero-area, non-planar faces)
// warn with the line and go on. Backend failures exit 1 with one error line, or warn and fall
// back to OSMesa under --backend auto.
#include <catch2/catch.hpp>
#include <fcntl.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>

#include "gl/Debug.h"
#include "gl/GL.h"
#include "gl/Objects.h"
#include "src/scene/Atlas.h"
#include "src/base/Error.h"
#include "src/scene/SceneLoader.h"
#include "tests/Support.h"

using namespace hemirad;
using Catch::Contains;

namespace {

namespace fs = std::filesystem;

int count(const std::string& text, const std::string& what) {
  int n = 0;
  for (size_t p = 0; (p = text.find(what, p)) != std::string::npos; p += what.size()) ++n;
  return n;
}

// Every output flag, into a fresh folder that must still be empty afterwards (no output, no
// temporary file).
struct Outputs {
  std::string dir, flags;
  explicit Outputs(const std::string& name) : dir(test::tempPath("out-" + name)) {
    fs::create_directories(dir);
    flags = " --out " + dir + "/view.exr --image " + dir + "/view.png --atlas " + dir + "/atlas.exr --ply " + dir +
            "/mesh.ply --report " + dir + "/report.json";
  }
  bool empty() const { return fs::is_empty(dir); }
};

// `hemirad ARGS` with every output flag: exit code 2, exactly one error line holding every one
// of `messages`, no output written.
void expectRefused(const std::string& name, const std::string& args, const std::vector<std::string>& messages,
                   const std::string& env = "") {
  Outputs out(name);
  test::Run run = test::hemirad(args + out.flags, env);
  INFO("hemirad " << args << "\n" << run.output);
  CHECK(run.exitCode == 2);
  CHECK(count(run.output, "hemirad: error:") == 1);
  for (const auto& m : messages) CHECK_THAT(run.output, Contains(m));
  CHECK(out.empty());
}

const std::string kMtl = "newmtl lamp\nKd 0.5 0.5 0.5\nKe 1 1 1\nnewmtl grey\nKd 0.5 0.5 0.5\n";
// Lines 1-6; a face on line 7 follows.
const std::string kQuad = "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nusemtl lamp\n";

// Writes s.obj and m.mtl into a fresh folder; returns the OBJ's path.
std::string writeScene(const std::string& name, const std::string& obj, const std::string& mtl = kMtl) {
  std::string dir = test::tempPath("scene-" + name);
  fs::create_directories(dir);
  std::ofstream(dir + "/m.mtl") << mtl;
  std::ofstream(dir + "/s.obj") << obj;
  return dir + "/s.obj";
}

std::string solve(const std::string& obj) { return "solve " + obj + " --shots 2 --quiet"; }

// The `--texel-size X` an error message suggests.
double suggestedTexelSize(const std::string& message) {
  std::smatch m;
  REQUIRE(std::regex_search(message, m, std::regex("use --texel-size ([0-9.e+-]+) or larger")));
  return std::stod(m[1]);
}

Scene unitSquare() {
  Scene scene;
  scene.path = "unit square";
  scene.addObject("square");
  scene.addPolygon(test::rectangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 1, 1), test::material(scene, 0.5, 1.0), 0);
  return scene;
}

// Captures what is written to stderr (fd 2) while `fn` runs.
template <class Fn>
std::string captureStderr(Fn&& fn) {
  std::string path = test::tempPath("stderr.txt");
  std::fflush(stderr);
  int saved = dup(2), fd = open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  dup2(fd, 2);
  close(fd);
  try {
    fn();
  } catch (...) {
    std::fflush(stderr);
    dup2(saved, 2);
    close(saved);
    throw;
  }
  std::fflush(stderr);
  dup2(saved, 2);
  close(saved);
  std::ostringstream text;
  text << std::ifstream(path).rdbuf();
  return text.str();
}

}  // namespace

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

TEST_CASE("Bad input: a non-planar polygon is split into triangles with a warning naming its line and the solve goes on",
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

TEST_CASE("Bad input: reflectance of 1 or more or below 0 is one error naming the MTL file and line",
          "[cli][bad-input]") {
  std::string high = writeScene("rho-high", kQuad + "f 1 2 3 4\n", "newmtl lamp\nKe 1 1 1\nKd 0.5 1 0.5\n");
  expectRefused("rho-high", solve(high), {"m.mtl:3: material 'lamp': reflectance Kd 1 is >= 1"});
  std::string low = writeScene("rho-low", kQuad + "f 1 2 3 4\n", "newmtl lamp\nKe 1 1 1\nKd 0.5 -0.1 0.5\n");
  expectRefused("rho-low", solve(low), {"m.mtl:3: material 'lamp': reflectance Kd -0.1 is negative"});
}

// ---- discretisation: texel size and element count against the GPU's limits

TEST_CASE("Bad input: a texel size whose atlas is over the GPU texture limit is one error naming the limit and a size "
          "that fits",
          "[cli][bad-input]") {
  std::string obj = writeScene("tiny-texels", kQuad + "f 1 2 3 4\n");
  expectRefused("tiny-texels", solve(obj) + " --texel-size 1e-5",
                {"texel size 1e-05 needs a", "GL_MAX_TEXTURE_SIZE", "use --texel-size", "or --elements"});
  expectRefused("absurd-texels", solve(obj) + " --texel-size 1e-12", {"GL_MAX_TEXTURE_SIZE", "use --texel-size"});
}

TEST_CASE("Bad input: an element count over the GPU texture limit is one error within seconds naming the limit",
          "[cli][bad-input]") {
  std::string obj = writeScene("many-elements", kQuad + "f 1 2 3 4\n");
  auto start = std::chrono::steady_clock::now();
  expectRefused("many-elements", solve(obj) + " --elements 268435456", {"GL_MAX_TEXTURE_SIZE", "use --texel-size"});
  CHECK(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() < 30);
  expectRefused("too-many-elements", solve(obj) + " --elements 268435457", {"--elements"});
}

TEST_CASE("An atlas over the texture limit is refused with a suggested texel size that does fit", "[cpu][bad-input]") {
  Scene scene = unitSquare();
  std::string message;
  try {
    buildAtlas(scene, 0.001, 64);
  } catch (const InputError& e) {
    message = e.what();
  }
  INFO(message);
  CHECK_THAT(message, Contains("over the GPU's limit of 64 texels a side"));
  double fit = suggestedTexelSize(message);
  Atlas atlas;
  REQUIRE_NOTHROW(atlas = buildAtlas(scene, fit, 64));
  CHECK(atlas.width <= 64);
  CHECK(atlas.height <= 64);
}

TEST_CASE("An atlas over the memory limit is refused naming the limit and a texel size that fits", "[cpu][bad-input]") {
  Scene scene = unitSquare();
  const std::size_t memory = 1 << 20;  // 1 MiB: about 8,000 texels
  std::string message;
  try {
    buildAtlas(scene, 0.001, 16384, memory);
  } catch (const InputError& e) {
    message = e.what();
  }
  INFO(message);
  CHECK_THAT(message, Contains("of memory, over the memory limit of 1.0 MiB"));
  double fit = suggestedTexelSize(message);
  REQUIRE_NOTHROW(buildAtlas(scene, fit, 16384, memory));
  CHECK_THROWS_AS(buildAtlas(scene, fit / 1.2, 16384, memory), InputError);  // and not far from the smallest
}

// ---- flags

TEST_CASE("Bad input: --texel-size with --elements is one error naming both flags", "[cli][bad-input]") {
  std::string obj = writeScene("both", kQuad + "f 1 2 3 4\n");
  expectRefused("both", solve(obj) + " --texel-size 0.1 --elements 100", {"--texel-size", "--elements", "excludes"});
}

TEST_CASE("Bad input: --converge outside (0, 1) is one error naming the flag", "[cli][bad-input]") {
  std::string obj = writeScene("converge", kQuad + "f 1 2 3 4\n");
  for (std::string c : {"0", "1", "1.5", "-0.1", "nan"})
    expectRefused("converge" + c, "solve " + obj + " --converge " + c, {"--converge"});
}

TEST_CASE("Bad input: an unknown flag is one error naming it", "[cli][bad-input]") {
  std::string obj = writeScene("unknown-flag", kQuad + "f 1 2 3 4\n");
  expectRefused("unknown-flag", solve(obj) + " --frobnicate 3", {"--frobnicate"});
}

TEST_CASE("Bad input: a non-numeric or out-of-range flag value is one error naming the flag", "[cli][bad-input]") {
  std::string obj = writeScene("values", kQuad + "f 1 2 3 4\n");
  for (std::string flag : {"--shots many", "--texel-size big", "--texel-size inf", "--texel-size -1", "--elements lots",
                           "--elements 0", "--width abc", "--exposure x", "--item-res 8", "--shooters-per-pass 65",
                           "--gpu -1"})
    expectRefused("values", solve(obj) + " " + flag, {flag.substr(0, flag.find(' '))});
}

TEST_CASE("Bad input: an output path in a missing folder or naming a folder is one error naming the flag before solving",
          "[cli][bad-input]") {
  std::string obj = writeScene("unwritable", kQuad + "f 1 2 3 4\n");
  std::string file = fs::path(obj).parent_path() / "m.mtl";  // a file, used as a folder below
  std::string folder = test::tempPath("a-folder");
  fs::create_directories(folder);
  for (auto [flag, path] : {std::pair<std::string, std::string>{"--out", "/no/such/folder/x.exr"},
                            {"--image", file + "/x.png"}, {"--report", folder}, {"--atlas", "/no/such/a.exr"},
                            {"--ply", folder}}) {
    test::Run run = test::hemirad(solve(obj) + " " + flag + " " + path);
    INFO(run.output);
    CHECK(run.exitCode == 2);
    CHECK(count(run.output, "hemirad: error:") == 1);
    CHECK_THAT(run.output, Contains(flag + " " + path));
  }
  CHECK(fs::is_empty(folder));
}

// ---- backends

TEST_CASE("Backend failure: a missing OSMesa library is one error naming the file, exit 1, no output", "[cli][backend]") {
  std::string obj = writeScene("no-osmesa", kQuad + "f 1 2 3 4\n");
  Outputs out("no-osmesa");
  test::Run run = test::hemirad(solve(obj) + out.flags, "HEMIRAD_OSMESA_LIBRARY=/no/such/libOSMesa.so.8");
  INFO(run.output);
  CHECK(run.exitCode == 1);
  CHECK(count(run.output, "hemirad: error:") == 1);
  CHECK_THAT(run.output, Contains("hemirad: error: osmesa: cannot load HEMIRAD_OSMESA_LIBRARY=/no/such/libOSMesa.so.8"));
  CHECK(out.empty());
}

TEST_CASE("Backend failure: a missing EGL library with --backend egl is one error naming the file, exit 1",
          "[cli][backend]") {
  std::string obj = writeScene("no-egl", kQuad + "f 1 2 3 4\n");
  Outputs out("no-egl");
  test::Run run = test::hemirad(solve(obj) + " --backend egl" + out.flags, "HEMIRAD_EGL_LIBRARY=/no/such/libEGL.so.1");
  INFO(run.output);
  CHECK(run.exitCode == 1);
  CHECK(count(run.output, "hemirad: error:") == 1);
  CHECK_THAT(run.output, Contains("hemirad: error: egl: cannot load HEMIRAD_EGL_LIBRARY=/no/such/libEGL.so.1"));
  CHECK(out.empty());
}

TEST_CASE("Backend failure: --backend auto without an EGL library warns and falls back to OSMesa", "[cli][backend]") {
  std::string obj = writeScene("auto", kQuad + "f 1 2 3 4\n");
  std::string report = test::tempPath("auto.json");
  test::Run run = test::hemirad(solve(obj) + " --backend auto --report " + report, "HEMIRAD_EGL_LIBRARY=/no/such/libEGL.so.1");
  INFO(run.output);
  REQUIRE(run.exitCode == 0);
  CHECK(count(run.output, "hemirad: warning:") == 1);
  CHECK_THAT(run.output, Contains("hemirad: warning: --backend auto: egl: cannot load HEMIRAD_EGL_LIBRARY=/no/such/libEGL.so.1"));
  CHECK_THAT(run.output, Contains("falling back to osmesa"));
  CHECK(nlohmann::json::parse(std::ifstream(report))["backend"] == "osmesa");
}

TEST_CASE("Backend failure: an EGL device index that does not exist is one error naming it, exit 1", "[cli][backend]") {
  std::string obj = writeScene("no-device", kQuad + "f 1 2 3 4\n");
  Outputs out("no-device");
  test::Run run = test::hemirad(solve(obj) + " --backend egl --gpu 99" + out.flags);
  INFO(run.output);
  CHECK(run.exitCode == 1);
  CHECK(count(run.output, "hemirad: error:") == 1);
  CHECK_THAT(run.output, Contains("egl: GPU 99 not usable"));
  CHECK(out.empty());
}

TEST_CASE("GL_OUT_OF_MEMORY allocating a buffer or texture is an error naming the allocation and its size", "[gl]") {
  test::backend();
  CHECK_THROWS_WITH(gl::Buffer(std::size_t(1) << 42), Contains("out of GPU memory allocating a buffer of 4398046511104 bytes (4096.00 GiB)"));
  CHECK_THROWS_WITH(gl::Texture(GL_RGBA32F, 16384, 16384, 2048),
                    Contains("out of GPU memory allocating a 16384 x 16384 x 2048 GL_RGBA32F texture (8192.00 GiB)"));
  CHECK(gl::takeError() == 0);
  CHECK_NOTHROW(gl::Buffer(64));  // and the context goes on working
}

TEST_CASE("With GL debug output every KHR_debug message is reported and a GL error names the driver's message", "[gl]") {
  test::backend();
  std::string error;
  std::string printed = captureStderr([&] {
    gl::enableDebugOutput();
    const char* low = "hemirad test: a low-severity message";
    gl::insertDebugMessage(1, false, low);
    gl::insertDebugMessage(2, true, "hemirad test: a notification");
    gl::Buffer().bind(0xdead);  // GL_INVALID_ENUM
    try {
      gl::checkErrors("the test");
    } catch (const gl::Error& e) {
      error = e.what();
    }
    gl::disableDebugOutput();
  });
  INFO(printed);
  CHECK_THAT(printed, Contains("hemirad: GL debug: other (low, id 1): hemirad test: a low-severity message"));
  CHECK_THAT(printed, Contains("hemirad: GL debug: marker (notification, id 2): hemirad test: a notification"));
  CHECK_THAT(printed, Contains("hemirad: GL debug: error (high"));
  CHECK_THAT(error, Contains("GL error 0x0500 (GL_INVALID_ENUM) in the test: "));
  CHECK(error.size() > std::string("GL error 0x0500 (GL_INVALID_ENUM) in the test: ").size());
  CHECK(gl::takeDebugError().empty());
}

TEST_CASE("A solve with --gl-debug runs clean: no GL debug error on the whole path", "[cli][backend]") {
  std::string obj = writeScene("gl-debug", kQuad + "f 1 2 3 4\n");
  std::string out = test::tempPath("gl-debug.png");
  test::Run run = test::hemirad(solve(obj) + " --gl-debug --image " + out);
  INFO(run.output);
  CHECK(run.exitCode == 0);
  CHECK(count(run.output, "hemirad: GL debug: error") == 0);
  CHECK(fs::exists(out));
}
