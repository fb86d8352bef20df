// Clusters (src/scene/Clusters.h): small separate parts of one object, material and facing share
// an element, so a cloud of tiny cubes costs elements by the space it fills, not by its faces;
// the shared elements keep the parts' true areas and come out right in a furnace.
#include <catch2/catch.hpp>

#include <array>
#include <set>

#include "src/scene/Clusters.h"
#include "tests/support/Support.h"

using namespace hemirad;

namespace {

constexpr int kCloudSide = 8;  // tiny cubes a side: 512 cubes, 3,072 faces
constexpr double kTinySide = 0.02, kSpacing = 0.07, kCloudStart = 0.22;

// A unit box (walls rho 0.5, emission `wallE`; a lamp on the ceiling if lampFace >= 0) holding a
// cloud of closed tiny cubes facing out (rho 0.5, emission `cloudE`).
Scene boxWithCloud(double wallE, double cloudE, int lampFace = -1) {
  Scene s = test::cube(0.5, wallE, lampFace);
  const int grey = test::material(s, 0.5, cloudE), cloud = s.addObject("cloud");
  const glm::dvec3 X(1, 0, 0), Y(0, 1, 0), Z(0, 0, 1);
  for (int i = 0; i < kCloudSide; ++i)
    for (int j = 0; j < kCloudSide; ++j)
      for (int k = 0; k < kCloudSide; ++k) {
        const glm::dvec3 o = glm::dvec3(kCloudStart) + kSpacing * glm::dvec3(i, j, k);
        const double w = kTinySide;
        s.addPolygon(test::rectangle(o, X, Z, w, w), grey, cloud);          // -y
        s.addPolygon(test::rectangle(o + w * Y, Z, X, w, w), grey, cloud);  // +y
        s.addPolygon(test::rectangle(o, Y, X, w, w), grey, cloud);          // -z
        s.addPolygon(test::rectangle(o + w * Z, X, Y, w, w), grey, cloud);  // +z
        s.addPolygon(test::rectangle(o, Z, Y, w, w), grey, cloud);          // -x
        s.addPolygon(test::rectangle(o + w * X, Y, Z, w, w), grey, cloud);  // +x
      }
  return s;
}

std::size_t clusteredCharts(const Atlas& atlas) {
  return std::size_t(
      std::count_if(atlas.charts.begin(), atlas.charts.end(), [](const Chart& c) { return c.clustered; }));
}

}  // namespace

TEST_CASE(
    "A cloud of 512 tiny cubes shares elements by object, material, facing and texel cube: fewer elements than "
    "faces, every face in one chart, element areas summing to the faces' areas",
    "[atlas]") {
  const Scene s = boxWithCloud(0.0, 0.0);
  const double ts = 1.0 / 6;
  const Atlas atlas = buildAtlas(s, ts);
  const std::size_t faces = std::size_t(6 * kCloudSide * kCloudSide * kCloudSide);
  INFO(atlas.elements << " elements, " << atlas.charts.size() << " charts, " << clusteredCharts(atlas) << " clusters");
  // 4 texel cubes a side hold the cloud, 6 facings each: at most 384 cluster elements.
  CHECK(atlas.elements <= 6 * 36 + 6 * 64);
  CHECK(clusteredCharts(atlas) > 0);
  std::vector<int> seen(s.polygons().size(), 0);
  for (const Chart& c : atlas.charts) {
    std::set<int> objects, materials;
    for (int p : c.polygons) {
      ++seen[std::size_t(p)];
      objects.insert(s.polygons()[std::size_t(p)].object), materials.insert(s.polygons()[std::size_t(p)].material);
      // One facing: the cubes' faces are axis-aligned, so a cluster's members face one way.
      if (c.clustered)
        CHECK(glm::dot(s.polygons()[std::size_t(p)].normal, s.polygons()[std::size_t(c.polygons[0])].normal) > 0.99);
    }
    CHECK(objects.size() == 1);
    CHECK(materials.size() == 1);
    if (c.clustered) CHECK(c.size == glm::ivec2(1));
  }
  CHECK(std::count(seen.begin(), seen.end(), 1) == std::ptrdiff_t(s.polygons().size()));
  double elementArea = 0;
  for (const glm::vec4& pa : atlas.positionArea) elementArea += pa.w;
  CHECK(elementArea == Approx(s.totalArea()).epsilon(1e-5));
  // Without clusters (a chart per polygon) every tiny face is an element of its own.
  CHECK(buildAtlas(s, ts, 16384, 0, kPolygonCharts).elements >= faces);
}

// Clusters approximate: one member receives for all and a shooter is seen from one piece per
// receiver (shaders/formfactor.glsl's clusterEye), so in this dense cloud the shared elements come
// out 5.8 % low (per-face elements: the same faces 1.5 % low, the rest 0.5 % high), the walls
// 0.9 % high; seen from the shooter's chosen eye alone they were 12.3 % low, and with every
// receiver behind the eye's plane skipped 10.5 %.
TEST_CASE(
    "In a furnace the shared elements of a cloud of tiny cubes come out within 8 % of E / (1 - rho) on average, "
    "the walls within 2 %",
    "[gl][heavy]") {  // ~2 s optimised, two solves of ~2,900 shots
  const Scene s = boxWithCloud(1.0, 1.0);
  ProgressiveSettings p;
  p.stop.targetConvergence = 0.999;
  p.visibility = Visibility::Bvh;
  // Traced on the host (HostTrace, as on llvmpipe) and by the GLSL walk (as on a GPU).
  const HostTraceUse trace = GENERATE(HostTraceUse::Always, HostTraceUse::Never);
  p.hostTrace = trace;
  const test::Solved r = test::solve(s, 1.0 / 6, p);
  REQUIRE(clusteredCharts(r.atlas) > 0);
  double error[2] = {0, 0}, area[2] = {0, 0};  // area-weighted (B - 2) / 2: walls, clusters
  for (std::size_t t = 0; t < r.B.size(); ++t) {
    if (r.atlas.polygonOf[t] == kNoPolygon) continue;
    const int k = r.atlas.charts[r.atlas.chartAt(t)].clustered;
    error[k] += (luminance(glm::dvec3(r.B[t])) - 2) / 2 * r.atlas.positionArea[t].w;
    area[k] += r.atlas.positionArea[t].w;
  }
  INFO((trace == HostTraceUse::Always ? "host" : "GLSL")
       << " trace; mean (B - 2) / 2: clusters " << error[1] / area[1] << ", walls " << error[0] / area[0]);
  CHECK(std::abs(error[1] / area[1]) < 0.08);
  CHECK(std::abs(error[0] / area[0]) < 0.02);
}

TEST_CASE(
    "Under a lamp, a cloud of tiny cubes sharing elements reflects, facing by facing, within 15 % of the power its "
    "faces reflect when each is an element of its own",
    "[gl][heavy]") {  // ~5 s optimised: the per-face solve
  const Scene s = boxWithCloud(0.0, 0.0, 1);
  ProgressiveSettings p;
  p.stop.targetConvergence = 0.99;
  const double ts = 1.0 / 6;
  const test::Solved clustered = test::solve(s, buildAtlas(s, ts), p);
  const test::Solved apart = test::solve(s, buildAtlas(s, ts, 16384, 0, kPolygonCharts), p);
  REQUIRE(clusteredCharts(clustered.atlas) > 0);
  // The cloud's reflected power (luminance B A) by the facing of its faces (the six axes).
  auto cloudPower = [&](const test::Solved& r) {
    std::array<double, 6> sum{};
    for (std::size_t t = 0; t < r.B.size(); ++t) {
      const std::uint32_t poly = r.atlas.polygonOf[t];
      if (poly == kNoPolygon || s.polygons()[poly].object != 1) continue;
      const glm::dvec3 n = s.polygons()[poly].normal;
      const int axis = std::abs(n.x) > 0.5 ? 0 : std::abs(n.y) > 0.5 ? 1 : 2;
      sum[std::size_t(2 * axis + (n[axis] < 0))] += luminance(glm::dvec3(r.B[t])) * r.atlas.positionArea[t].w;
    }
    return sum;
  };
  const std::array<double, 6> a = cloudPower(clustered), b = cloudPower(apart);
  INFO(clustered.atlas.elements << " elements clustered, " << apart.atlas.elements << " apart");
  for (std::size_t f = 0; f < 6; ++f) {
    INFO("facing " << f << ": clustered " << a[f] << ", apart " << b[f]);
    CHECK(a[f] == Approx(b[f]).epsilon(0.15));  // 6-13 % low (the furnace test says why)
  }
}
