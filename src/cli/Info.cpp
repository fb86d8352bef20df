#include <fmt/format.h>

#include <map>

#include "src/scene/Atlas.h"
#include "src/scene/ItemMesh.h"
#include "src/cli/Solve.h"

namespace hemirad {

int runInfo(const InfoOptions& o) {
  Scene scene = loadScene(o.scene, o.load);
  double ts = chooseTexelSize(scene, o.discretisation);
  Atlas atlas = buildAtlas(scene, ts);
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
  fmt::print("emitters     {} polygons, emitted power {:.6g} (luminance E*A)\n", emitters, scene.emittedPower() / (u * u));
  fmt::print("texel size   {:.6g}\nelements     {}\natlas        {} x {}\n", ts / u, atlas.elements, atlas.width, atlas.height);
  fmt::print("item mesh    {} triangles at --item-subdiv {}\n", itemTriangleCount(scene, o.itemSubdivision),
             o.itemSubdivision);
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
