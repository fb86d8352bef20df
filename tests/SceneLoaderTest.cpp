#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include "src/base/Error.h"
#include "src/scene/SceneLoader.h"
#include "tests/support/Files.h"
#include "tests/support/Support.h"

using namespace hemirad;
using Catch::Contains;

namespace {
const char* kMtl =
    "newmtl white\nKd 0.5 0.5 0.5\n\nnewmtl lamp\nKd 0 0 0\nKe 2 2 2\nKa 0 0 0\n\nnewmtl thesis_lamp\nKd 0 0 0\nKa 3 3 "
    "3\n";

// Writes NAME.obj (+ scene.mtl) in a fresh folder and returns the OBJ's path.
std::string writeScene(const std::string& name, const std::string& obj, const std::string& mtl = kMtl) {
  return test::writeScene(name, obj, mtl, name + ".obj", "scene.mtl");
}

const std::string kQuads =
    "mtllib scene.mtl\n"
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
    "v 0 0 1\nv 0 1 1\nv 1 1 1\nv 1 0 1\n"
    "o floor\nusemtl white\nf 1 2 3 4\n"
    "o lamp\nusemtl lamp\nf 5 6 7 8\n";
}  // namespace

TEST_CASE("OBJ loading keeps polygons, materials (Kd, Ke) and o names", "[cpu]") {
  Scene s = loadScene(writeScene("quads", kQuads));
  REQUIRE(s.polygons().size() == 2);
  REQUIRE(s.objects.size() == 2);
  CHECK(s.objects[0].name == "floor");
  CHECK(s.objects[1].name == "lamp");
  const ScenePolygon& lamp = s.polygons()[1];
  CHECK(lamp.vertices.size() == 4);  // a quad stays a quad
  CHECK(lamp.normal.z == Approx(-1.0));
  CHECK(s.materials[lamp.material].emission.x == Approx(2.0));
  CHECK(s.materials[s.polygons()[0].material].reflectance.y == Approx(0.5));
  CHECK(s.warnings.empty());
  CHECK(s.mesh().n_faces() == 2);
}

TEST_CASE("Emission from Ka (--emission ka) reads lights from Ka, the thesis's convention", "[cpu]") {
  std::string obj = kQuads;
  obj.replace(obj.find("usemtl lamp"), 11, "usemtl thesis_lamp");
  Scene s = loadScene(writeScene("ka", obj), {EmissionSource::Ka});
  CHECK(s.materials[s.polygons()[1].material].emission.x == Approx(3.0));
  CHECK_THROWS_WITH(validateSolvable(loadScene(writeScene("ke", obj))), Contains("no emitter"));
}

TEST_CASE("Bad scenes are refused with the file and line", "[cpu]") {
  SECTION("missing file") { CHECK_THROWS_WITH(loadScene("/nonexistent/x.obj"), Contains("x.obj: no such file")); }
  SECTION("missing MTL") {
    std::string obj = kQuads;
    obj.replace(0, 16, "mtllib nothere.mtl");
    CHECK_THROWS_WITH(loadScene(writeScene("nomtl", obj)), Contains(":1: material library 'nothere.mtl' not found"));
  }
  SECTION("unknown material") {
    std::string obj = kQuads;
    obj.replace(obj.find("usemtl lamp"), 11, "usemtl nope");
    CHECK_THROWS_WITH(loadScene(writeScene("unknown", obj)), Contains(":14: unknown material 'nope'"));
  }
  SECTION("NaN and infinite coordinates") {
    std::string obj = kQuads;
    obj.replace(obj.find("v 1 0 0"), 7, "v nan 0 0");
    CHECK_THROWS_WITH(loadScene(writeScene("nan", obj)), Contains(":3: vertex coordinate is not a finite number"));
    obj = kQuads;
    obj.replace(obj.find("v 1 1 0"), 7, "v 1 inf 0");
    CHECK_THROWS_WITH(loadScene(writeScene("inf", obj)), Contains(":4: vertex coordinate is not a finite number"));
  }
  SECTION("reflectance above 1") {
    CHECK_THROWS_WITH(loadScene(writeScene("rho", kQuads, "newmtl white\nKd 1.01 0.5 0.5\nnewmtl lamp\nKe 1 1 1\n")),
                      Contains("material 'white': reflectance Kd 1.01 is above 1"));
  }
  SECTION("face indexing a missing vertex") {
    CHECK_THROWS_WITH(loadScene(writeScene("index", kQuads + "f 1 2 99\n")), Contains("vertex"));
  }
}

TEST_CASE("Degenerate faces are skipped and non-planar ones triangulated, with warnings", "[cpu]") {
  std::string obj = kQuads +
                    "v 2 0 0\nv 3 0 0\nv 4 0 0\n"             // 9-11: collinear
                    "v 0 0 3\nv 1 0 3\nv 1 1 3.5\nv 0 1 3\n"  // 12-15: bent quad
                    "o junk\nusemtl white\nf 9 10 11\nf 12 13 14 15\nf 1 1 2\n";
  Scene s = loadScene(writeScene("repairs", obj));
  REQUIRE(s.warnings.size() == 3);
  CHECK_THAT(s.warnings[0].text(), Contains(":25: degenerate face"));
  CHECK_THAT(s.warnings[1].text(), Contains(":26: non-planar polygon split into triangles"));
  CHECK_THAT(s.warnings[2].text(), Contains(":27: degenerate face"));
  CHECK(s.polygons().size() == 4);  // floor, lamp, two triangles of the bent quad
}

TEST_CASE("A scene without emitters is refused before solving", "[cpu]") {
  std::string obj = kQuads;
  obj.replace(obj.find("usemtl lamp"), 11, "usemtl white");
  CHECK_THROWS_AS(validateSolvable(loadScene(writeScene("dark", obj))), InputError);
}

TEST_CASE(
    "Scene warnings print each of a rare kind, one line for a frequent kind, and at most kWarningLines lines "
    "with the last counting what is left out",
    "[cpu]") {
  // Kind k is seen k % 6 + 1 times; 3 * kWarningLines kinds cannot all fit.
  std::vector<SceneWarning> warnings;
  const std::size_t kinds = 3 * kWarningLines;
  for (std::size_t k = 0; k < kinds; ++k)
    for (std::size_t i = 0; i <= k % 6; ++i)
      warnings.push_back({fmt::format("s.obj:{}", 100 * k + i), fmt::format("kind {}", k)});
  const std::vector<std::string> lines = warningLines(warnings);
  REQUIRE(lines.size() == kWarningLines);
  // Walk the kinds in order: each either as its warnings, or one grouped line.
  std::size_t line = 0, shown = 0, kindsShown = 0;
  for (std::size_t k = 0; k < kinds; ++k, ++kindsShown) {
    const std::size_t n = k % 6 + 1, needed = n <= kWarningPlaces ? n : 1;
    if (line + needed + 1 > kWarningLines) break;  // the last line is the count of the rest
    if (n <= kWarningPlaces) {
      for (std::size_t i = 0; i < n; ++i) CHECK(lines[line++] == fmt::format("s.obj:{}: kind {}", 100 * k + i, k));
    } else {
      CHECK(lines[line++] == fmt::format("{} faces: kind {} (first at s.obj:{}, s.obj:{}, s.obj:{}, ...)", n, k,
                                         100 * k, 100 * k + 1, 100 * k + 2));
    }
    shown += n;
  }
  REQUIRE(line == lines.size() - 1);
  CHECK(lines.back() ==
        fmt::format("{} more warnings of {} other kinds not shown", warnings.size() - shown, kinds - kindsShown));
  CHECK(withThousands(87432) == "87,432");
  CHECK(withThousands(999) == "999");
}
