#include <catch2/catch.hpp>
#include <cmath>
#include <nlohmann/json.hpp>

#include "src/scene/ContactCuts.h"
#include "src/scene/Contacts.h"
#include "src/scene/SceneLoader.h"
#include "src/solver/ProgressiveSolver.h"
#include "tests/bad_input/BadInput.h"
#include "tests/support/Files.h"
#include "tests/support/Support.h"

using namespace hemirad;

namespace {

const glm::dvec3 X(1, 0, 0), Y(0, 1, 0), Z(0, 0, 1);

// A box of side `side` and height `height` standing at lo (its lowest corner): four sides facing out and a top.
void addBox(Scene& s, glm::dvec3 lo, double side, double height, int material, int object) {
  const glm::dvec3 hi = lo + glm::dvec3(side, 0, side);
  s.addPolygon(test::rectangle(lo, Z, Y, side, height), material, object);                  // faces -x
  s.addPolygon(test::rectangle({hi.x, lo.y, lo.z}, Y, Z, height, side), material, object);  // faces +x
  s.addPolygon(test::rectangle(lo, Y, X, height, side), material, object);                  // faces -z
  s.addPolygon(test::rectangle({lo.x, lo.y, hi.z}, X, Y, side, height), material, object);  // faces +z
  s.addPolygon(test::rectangle(lo + height * Y, Z, X, side, side), material, object);       // the top
}

// A 4 x 4 floor (y = 0, facing up) with a 1 x 0.5 x 1 box `lift` over it, and optionally a 2.5-high
// ceiling with a 0.4-wide lamp 0.5 mm under it (the contact distance: 1e-3 of the 6.2 diagonal).
Scene room(double lift, bool ceiling) {
  Scene s;
  const int grey = test::material(s, 0.5, 0.0), lamp = test::material(s, 0.0, 10.0);
  s.addPolygon(test::rectangle({-2, 0, -2}, Z, X, 4, 4), grey, s.addObject("floor"));
  addBox(s, {-0.5, lift, -0.5}, 1, 0.5, grey, s.addObject("box"));
  if (ceiling) {
    s.addPolygon(test::rectangle({-2, 2.5, -2}, X, Z, 4, 4), grey, s.addObject("ceiling"));  // faces down
    s.addPolygon(test::rectangle({-0.2, 2.5 - 5e-4, -0.2}, X, Z, 0.4, 0.4), lamp, s.addObject("lamp"));
  }
  return s;
}

std::string objectOf(const Scene& s, int polygon) {
  return s.objects[std::size_t(s.polygons()[std::size_t(polygon)].object)].name;
}

// The part of convex `p` inside convex counter-clockwise `clip` (x, z plane).
Poly2 clipConvex(Poly2 p, const Poly2& clip) {
  for (std::size_t e = 0; e < clip.size() && p.size() >= 3; ++e) {
    const glm::dvec2 a = clip[e], d = clip[(e + 1) % clip.size()] - a;
    auto side = [&](glm::dvec2 q) { return d.x * (q.y - a.y) - d.y * (q.x - a.x); };
    Poly2 out;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const glm::dvec2 q = p[i], r = p[(i + 1) % p.size()];
      const double sq = side(q), sr = side(r);
      if (sq >= 0) out.push_back(q);
      if ((sq >= 0) != (sr >= 0)) out.push_back(q + (r - q) * (sq / (sq - sr)));
    }
    p = std::move(out);
  }
  return p;
}

Poly2 xz(const Poly3& p) {
  Poly2 out;
  for (const glm::dvec3& v : p) out.push_back({v.x, v.z});
  if (signedArea(out) < 0) std::reverse(out.begin(), out.end());
  return out;
}

// The footprint of object `name` (its vertices at y = 0, counter-clockwise in x, z).
Poly2 footprint(const Scene& s, const std::string& name) {
  Poly2 out;
  for (std::size_t p = 0; p < s.polygons().size(); ++p)
    if (objectOf(s, int(p)) == name)
      for (const glm::dvec3& v : s.polygons()[p].vertices)
        if (v.y == 0 && std::find(out.begin(), out.end(), glm::dvec2(v.x, v.z)) == out.end()) out.push_back({v.x, v.z});
  glm::dvec2 c(0.0);  // inside: the vertex mean (the unsorted loop's area centroid is not)
  for (glm::dvec2 v : out) c += v / double(out.size());
  std::sort(out.begin(), out.end(), [&](glm::dvec2 a, glm::dvec2 b) {
    return std::atan2(a.y - c.y, a.x - c.x) < std::atan2(b.y - c.y, b.x - c.x);
  });
  return out;
}

// Floor elements of `atlas` with pieces both inside and outside one of the footprints (by area).
int straddlingElements(const Scene& s, const Atlas& atlas, const std::vector<Poly2>& footprints) {
  int straddling = 0;
  for (int y = 0; y < atlas.height; ++y)
    for (int x = 0; x < atlas.width; ++x) {
      const std::size_t t = std::size_t(y) * std::size_t(atlas.width) + std::size_t(x);
      if (atlas.polygonOf[t] == kNoPolygon || objectOf(s, int(atlas.polygonOf[t])) != "floor") continue;
      for (const Poly2& f : footprints) {
        double in = 0, total = 0;
        for (const Poly3& piece : atlas.elementShape(s, x, y)) {
          const Poly2 q = xz(piece), both = clipConvex(q, f);
          total += signedArea(q), in += both.size() >= 3 ? signedArea(both) : 0;
        }
        straddling += in > 1e-9 * total && in < (1 - 1e-9) * total;
      }
    }
  return straddling;
}

}  // namespace

TEST_CASE("Contact cuts cut the Cornell box floor exactly along the blocks' footprints", "[cpu][discontinuity]") {
  const Scene scene = loadScene(test::sourcePath("scenes/cornell/cornell.obj"));
  const Atlas atlas = buildAtlas(scene, 20.0);
  const std::vector<ContactLine> lines = findContacts(scene, atlas, contactDistance(scene));
  CHECK(lines.size() == 8);  // the blocks' four bottom edges each; the walls meet the floor on its outline
  for (const ContactLine& l : lines) CHECK(objectOf(scene, atlas.charts[std::size_t(l.chart)].polygon) == "floor");
  const std::optional<ContactLayout> cut = cutAlongContacts(scene, atlas, lines);
  REQUIRE(cut);
  const Atlas cutAtlas = buildAtlas(cut->scene, cut->specs, atlas.texelSize);
  // The floor: its lit part around the blocks (one chart, whatever the extensions of the
  // footprints' edges cut) and the part under each block.
  CHECK(cut->pieces == 11);
  CHECK(cutAtlas.charts.size() == atlas.charts.size() + 2);
  const std::vector<Poly2> footprints{footprint(scene, "short_block"), footprint(scene, "tall_block")};
  REQUIRE(footprints[0].size() == 4);
  REQUIRE(footprints[1].size() == 4);
  // Every footprint edge lies on the outlines of the pieces on both its sides.
  for (const Poly2& f : footprints)
    for (std::size_t e = 0; e < f.size(); ++e)
      for (double t = 0.05; t < 1; t += 0.1) {
        const glm::dvec2 a = f[e], b = f[(e + 1) % f.size()], p = a + t * (b - a);
        int outlines = 0;
        for (std::size_t q = 0; q < cut->scene.polygons().size(); ++q) {
          if (objectOf(cut->scene, int(q)) != "floor") continue;
          const Poly2 piece = xz(cut->scene.polygons()[q].vertices);
          for (std::size_t i = 0; i < piece.size(); ++i) {
            const glm::dvec2 u = piece[i], d = piece[(i + 1) % piece.size()] - u;
            const double s = std::clamp(glm::dot(p - u, d) / glm::dot(d, d), 0.0, 1.0);
            outlines += glm::length(p - (u + s * d)) < 1e-9;
          }
        }
        INFO("footprint edge " << e << " at " << t);
        CHECK(outlines == 2);
      }
  double before = 0, after = 0;
  for (std::size_t p = 0; p < scene.polygons().size(); ++p)
    if (objectOf(scene, int(p)) == "floor") before += scene.polygons()[p].area;
  for (std::size_t p = 0; p < cut->scene.polygons().size(); ++p)
    if (objectOf(cut->scene, int(p)) == "floor") after += cut->scene.polygons()[p].area;
  CHECK(std::abs(after - before) <= 1e-9 * before);
  CHECK(cut->scene.totalArea() == Approx(scene.totalArea()).epsilon(1e-12));
  CHECK(straddlingElements(scene, atlas, footprints) > 20);  // uncut: texels along every footprint edge
  CHECK(straddlingElements(cut->scene, cutAtlas, footprints) == 0);
}

TEST_CASE("Only touching polygons cut: a block 10 cm over the floor does not, a lamp 0.5 mm under the ceiling does",
          "[cpu][discontinuity]") {
  for (double lift : {0.0, 0.1}) {
    const Scene scene = room(lift, true);
    const Atlas atlas = buildAtlas(scene, 0.25);
    const std::vector<ContactLine> lines = findContacts(scene, atlas, contactDistance(scene));
    int floor = 0, ceiling = 0;
    for (const ContactLine& l : lines) {
      const std::string receiver = objectOf(scene, atlas.charts[std::size_t(l.chart)].polygon);
      floor += receiver == "floor" && objectOf(scene, l.occluder) == "box";
      ceiling += receiver == "ceiling" && objectOf(scene, l.occluder) == "lamp";
    }
    INFO("box lifted " << lift);
    CHECK(floor == (lift == 0 ? 4 : 0));
    CHECK(ceiling == 4);
    CHECK(int(lines.size()) == floor + ceiling);
  }
  const Scene floating = room(0.1, false);
  const Atlas atlas = buildAtlas(floating, 0.25);
  CHECK_FALSE(cutAlongContacts(floating, atlas, findContacts(floating, atlas, contactDistance(floating))));
}

TEST_CASE("A contact less than a texel across is found but not cut", "[cpu][discontinuity]") {
  Scene s;
  const int grey = test::material(s, 0.5, 0.0);
  s.addPolygon(test::rectangle({-2, 0, -2}, Z, X, 4, 4), grey, s.addObject("floor"));
  addBox(s, {0.01, 0, 0.02}, 0.2, 0.2, grey, s.addObject("foot"));
  for (double texel : {0.25, 0.1}) {
    const Atlas atlas = buildAtlas(s, texel);
    const std::vector<ContactLine> lines = findContacts(s, atlas, contactDistance(s));
    CHECK(lines.size() == 4);
    const std::optional<ContactLayout> cut = cutAlongContacts(s, atlas, lines);
    INFO("texel " << texel);
    CHECK(bool(cut) == (texel < 0.2));  // kMinContactCells: the 0.2-wide foot against the cell
  }
}

TEST_CASE("Contact cuts leave a scene without contacts as it is, hash for hash", "[heavy][cli][discontinuity]") {
  auto hashOf = [](const std::string& flags) {
    const std::string report = test::tempPath("disc" + std::to_string(std::hash<std::string>{}(flags)) + ".json");
    const test::Run run = test::hemirad("solve " + test::sourcePath("scenes/analytic/blocked_squares.obj") +
                                        " --elements 800 --shots 32 --item-res 128 " + flags + " --report " + report);
    INFO(run.output);
    REQUIRE(run.exitCode == 0);
    return test::readJson(report)["radiosity_hash"].get<std::string>();
  };
  CHECK(hashOf("--discontinuities contact") == hashOf("--discontinuities off"));
}

namespace {

// A 4 x 4 floor with a 0.8 x 0.4 x 0.8 box on it, off the texel lattice, lit from the side by a
// 0.3-wide lamp 1.2 up: the floor is lit right to the box's base on the lamp's side.
Scene boxOnFloor() {
  Scene s;
  const int grey = test::material(s, 0.5, 0.0), lamp = test::material(s, 0.0, 20.0);
  s.addPolygon(test::rectangle({-2, 0, -2}, Z, X, 4, 4), grey, s.addObject("floor"));
  addBox(s, {-0.4 + 0.0437, 0, -0.4 + 0.0291}, 0.8, 0.4, grey, s.addObject("box"));
  s.addPolygon(test::rectangle({0.85, 1.2, -0.15}, X, Z, 0.3, 0.3), lamp, s.addObject("lamp"));
  return s;
}

struct Layout {
  Scene scene;
  Atlas atlas;
};

Layout layoutOf(const Scene& s, double texel, bool cut) {
  Atlas atlas = buildAtlas(s, texel);
  if (!cut) return {s, std::move(atlas)};
  std::optional<ContactLayout> c = cutAlongContacts(s, atlas, findContacts(s, atlas, contactDistance(s)));
  REQUIRE(c);
  Atlas cutAtlas = buildAtlas(c->scene, c->specs, texel);
  return {std::move(c->scene), std::move(cutAtlas)};
}

std::vector<glm::vec4> solved(const Layout& l) {
  test::backend();
  SolverState state(l.scene, l.atlas);
  ProgressiveSettings settings;
  settings.stop.targetConvergence = 0.99;
  ProgressiveSolver solver(state, settings);
  advanceToStop(solver, {});
  return state.readRadiosity();
}

// The luminance shown at floor point p (the camera's lookup, Atlas::sample).
double floorAt(const Layout& l, const std::vector<glm::vec4>& B, glm::dvec3 p) {
  for (std::size_t q = 0; q < l.scene.polygons().size(); ++q) {
    if (objectOf(l.scene, int(q)) != "floor") continue;
    const Poly2 piece = xz(l.scene.polygons()[q].vertices);
    bool in = true;
    for (std::size_t i = 0; i < piece.size() && in; ++i) {
      const glm::dvec2 a = piece[i], d = piece[(i + 1) % piece.size()] - a;
      in = d.x * (p.z - a.y) - d.y * (p.x - a.x) >= 0;
    }
    if (in) return luminance(glm::dvec3(l.atlas.sample(B, int(q), l.atlas.atlasCoord(int(q), p))));
  }
  return -1;
}

}  // namespace

TEST_CASE(
    "Contact cuts bring the floor's light beside a box closer to a solve of 16 times the elements, at equal elements",
    "[gl][heavy][discontinuity]") {
  const Scene scene = boxOnFloor();
  const double coarse = 4.0 / 32;
  const Layout cut = layoutOf(scene, coarse, true);
  double texel = coarse;  // uniform texels: at least as many elements as the cut layout
  while (buildAtlas(scene, texel).elements < cut.atlas.elements) texel *= 0.995;
  const Layout uniform = layoutOf(scene, texel, false), fine = layoutOf(scene, coarse / 4, true);
  const std::vector<glm::vec4> Bcut = solved(cut), Buniform = solved(uniform), Bfine = solved(fine);
  const Poly2 f = footprint(scene, "box");
  // Per footprint side (0: -z, 1: +x, the lamp's, 2: +z, 3: -x): |error| sums of cut and uniform, and B's sum.
  std::vector<glm::dvec3> err(f.size(), glm::dvec3(0.0));
  for (std::size_t e = 0; e < f.size(); ++e) {
    const glm::dvec2 a = f[e], d = f[(e + 1) % f.size()] - a, out = glm::normalize(glm::dvec2(d.y, -d.x));
    for (double dist : {0.01, 0.03, 0.06, 0.09, 0.12})  // within a coarse texel of the box
      for (double t = 0.1; t < 0.95; t += 0.1) {
        const glm::dvec2 q = a + t * d + dist * out;
        const glm::dvec3 p(q.x, 0, q.y);
        const double ref = floorAt(fine, Bfine, p);
        REQUIRE(ref >= 0);
        err[e] += glm::dvec3(std::abs(floorAt(cut, Bcut, p) - ref), std::abs(floorAt(uniform, Buniform, p) - ref), ref);
      }
  }
  const glm::dvec3 all = err[0] + err[1] + err[2] + err[3];
  INFO("elements: cut " << cut.atlas.elements << ", uniform " << uniform.atlas.elements << ", reference "
                        << fine.atlas.elements << "; mean |error| / mean B beside the box: cut " << all.x / all.z
                        << ", uniform " << all.y / all.z << "; on the lamp's side: cut " << err[1].x / err[1].z
                        << ", uniform " << err[1].y / err[1].z);
  CHECK(uniform.atlas.elements >= cut.atlas.elements);
  CHECK(err[1].x < 0.25 * err[1].y);  // lit to the base: the straddling texels were far too dark
  CHECK(all.x < 0.7 * all.y);
}

TEST_CASE("Bad input: contact cuts with input UVs is one error before the scene is read", "[heavy][cli][bad-input]") {
  test::bad_input::expectRefused(
      "uv-contact",
      "solve " + test::sourcePath("scenes/cornell/cornell.gltf") +
          " --uv input --discontinuities contact --shots 2 --quiet",
      {"--discontinuities contact cuts projection charts; it cannot take --uv input's charts"});
}
