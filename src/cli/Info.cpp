#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <map>

#include "gl/Backend.h"
#include "src/base/Error.h"
#include "src/base/ResidentMemory.h"
#include "src/cli/Solve.h"
#include "src/output/Lightmap.h"
#include "src/scene/Atlas.h"
#include "src/scene/AtlasPacker.h"
#include "src/scene/AtlasUse.h"
#include "src/scene/ItemMesh.h"
#include "src/solver/ProgressiveSolver.h"
#include "src/solver/SolverState.h"

namespace hemirad {

namespace {

std::size_t triangleCount(const Scene& scene) {
  std::size_t n = 0;
  for (const auto& p : scene.polygons()) n += p.vertices.size() - 2;
  return n;
}

// What a progressive solve at solve's defaults holds: the GPU buffers and textures its state and
// solver allocate (set up, not run), and this process's resident peak by then. A scene the GPU
// cannot hold says why here.
void printFootprint(const Scene& scene, const Atlas& atlas, const InfoOptions& o) {
  const std::size_t triangles = triangleCount(scene);
  try {
    auto backend = gl::createBackend({});
    const std::size_t before = gl::allocatedBytes();
    SolverState state(scene, atlas);
    ProgressiveSettings settings;
    settings.itemSubdivision = o.itemSubdivision;
    ProgressiveSolver solver(state, settings);
    fmt::print("gpu memory   {} at solve's defaults\n",
               bytesPerUnit(gl::allocatedBytes() - before, atlas.elements, triangles));
  } catch (const std::exception& e) {  // InputError or gl::Error: the solve would fail the same way
    fmt::print("gpu memory   not measured: {}\n", e.what());
  }
  if (const std::optional<ResidentMemory> m = residentMemory())
    fmt::print("resident     {} at its peak\n", bytesPerUnit(m->peakBytes, atlas.elements, triangles));
}

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Where the texels go, in the solve's atlas and in the lightmap `--gltf` exports (issue 29).
void printTexelUse(const Atlas& atlas, double atlasSeconds) {
  const AtlasUse u = atlasUse(atlas);
  std::vector<glm::ivec2> sizes;
  for (const Chart& c : atlas.charts) sizes.push_back(c.size);
  auto start = std::chrono::steady_clock::now();
  packAtlasCharts(sizes, 16384);  // again, timed alone
  fmt::print(
      "atlas use    {:.1f} % elements: {:.1f} % of chart cells, charts {:.1f} % of the atlas (built in {:.3f} s, "
      "packed in {:.3f} s)\n",
      100 * u.texelUse(), 100 * u.cellUse(), 100 * u.packing(), atlasSeconds, secondsSince(start));
  start = std::chrono::steady_clock::now();
  const Lightmap map = buildLightmap(atlas, std::vector<glm::vec4>(atlas.polygonOf.size(), glm::vec4(0.0f)));
  fmt::print("lightmap     {} x {}, texel use {:.1f} %, charts{} {:.1f} % (in {:.3f} s)\n", map.width, map.height,
             100 * map.texelUse(), gutterWords(map.gutter), 100 * map.packing(), secondsSince(start));
}

}  // namespace

int runInfo(const InfoOptions& o) {
  Scene scene = loadScene(o.scene, o.load);
  const auto atlasStart = std::chrono::steady_clock::now();  // the texel size's search included
  Atlas atlas = buildAtlas(scene, o.discretisation, 16384);
  const double ts = atlas.texelSize;
  const double atlasSeconds = secondsSince(atlasStart);
  const double u = scene.unitScale;  // printed in the file's units
  glm::dvec3 lo = scene.boundsMin() / u, hi = scene.boundsMax() / u;

  struct Row {
    int polygons = 0;
    double area = 0;
    std::size_t elements = 0;
    std::map<std::string, int> materials;
  };
  std::vector<Row> rows(scene.objects.size());
  int emitters = 0;
  for (const auto& p : scene.polygons()) {
    Row& r = rows[p.object];
    ++r.polygons;
    r.area += p.area / (u * u);
    ++r.materials[scene.materials[p.material].name];
    emitters += scene.materials[p.material].emissive();
  }
  for (std::uint32_t id : atlas.polygonOf)
    if (id != kNoPolygon) ++rows[scene.polygons()[id].object].elements;

  fmt::print("scene        {}\n", o.scene);
  fmt::print("bounds       ({:.4g}, {:.4g}, {:.4g}) to ({:.4g}, {:.4g}, {:.4g})\n", lo.x, lo.y, lo.z, hi.x, hi.y, hi.z);
  fmt::print("objects      {}\npolygons     {}\nmaterials    {}\n", scene.objects.size(), scene.polygons().size(),
             scene.materials.size());
  fmt::print("area         {:.6g}\n", scene.totalArea() / (u * u));
  fmt::print("emitters     {} polygons, emitted power {:.6g} (luminance E*A)\n", emitters,
             scene.emittedPower() / (u * u));
  fmt::print("texel size   {:.6g}\nelements     {}\natlas        {} x {}\n", ts / u, atlas.elements, atlas.width,
             atlas.height);
  std::size_t lscm = 0, clusters = 0, clustered = 0;  // clusters of small charts (Clusters.h), their polygons
  for (const Chart& c : atlas.charts) {
    lscm += c.uvMapped() && !c.clustered, clusters += c.clustered;
    clustered += c.clustered ? c.polygons.size() : 0;
  }
  fmt::print("charts       {} {}, {} clusters of {} polygons (texel use {:.1f} %)\n", atlas.charts.size(),
             o.discretisation.uv == UvSource::Input
                 ? std::string("from the input's UV islands (--uv input)")
                 : fmt::format("at --chart-angle {:g}, {} of them LSCM", o.discretisation.chartAngle, lscm),
             clusters, clustered, 100.0 * double(atlas.elements) / std::max(1.0, double(atlas.width) * atlas.height));
  fmt::print("item mesh    {} triangles at --item-subdiv {}\n", itemTriangleCount(scene, o.itemSubdivision),
             o.itemSubdivision);
  fmt::print("triangles    {}\n", triangleCount(scene));
  printTexelUse(atlas, atlasSeconds);
  printFootprint(scene, atlas, o);
  fmt::print("warnings     {}\n", scene.warnings.size());
  for (const auto& line : warningLines(scene.warnings)) fmt::print("  {}\n", line);
  fmt::print("\n{:<20} {:>8} {:>12} {:>9}  materials\n", "object", "polygons", "area", "elements");
  for (size_t i = 0; i < rows.size(); ++i) {
    std::string mats;
    for (const auto& [name, count] : rows[i].materials) mats += (mats.empty() ? "" : ", ") + name;
    fmt::print("{:<20} {:>8} {:>12.6g} {:>9}  {}\n", scene.objects[i].name, rows[i].polygons, rows[i].area,
               rows[i].elements, mats);
  }
  if (!emitters) fmt::print("\nno emitter: {}: `hemirad solve` needs one\n", noEmitterReason(scene));
  return 0;
}

}  // namespace hemirad
