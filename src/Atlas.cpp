#include "src/Atlas.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "src/Error.h"

namespace hemirad {

namespace {

constexpr int kGutter = 1;
// Cuts smaller than this fraction of a texel are numerical slivers, not elements.
constexpr double kMinCutFraction = 1e-9;

struct ChartShape {
  PlaneFrame frame;
  Poly2 poly;        // polygon in chart plane coordinates
  glm::dvec2 corner;  // lower-left of the texel grid
  glm::ivec2 size;
};

// The grid is centred on the polygon's bounds so partial texels are shared by both sides.
ChartShape chartShape(const ScenePolygon& p, double ts) {
  ChartShape c;
  c.frame = planeFrame(p.vertices, p.normal);
  glm::dvec2 lo(1e300), hi(-1e300);
  for (auto& v : p.vertices) {
    glm::dvec2 q = c.frame.project(v);
    c.poly.push_back(q);
    lo = glm::min(lo, q), hi = glm::max(hi, q);
  }
  glm::dvec2 extent = hi - lo;
  c.size = glm::max(glm::ivec2(glm::ceil(extent / ts - 1e-9)), glm::ivec2(1));
  c.corner = lo - (glm::dvec2(c.size) * ts - extent) * 0.5;
  return c;
}

template <class Fn>  // fn(i, j, cut polygon in plane coordinates)
void forEachCut(const ChartShape& c, double ts, Fn&& fn) {
  for (int j = 0; j < c.size.y; ++j)
    for (int i = 0; i < c.size.x; ++i) {
      Poly2 cut = clipToBox(c.poly, c.corner + glm::dvec2(i, j) * ts, c.corner + glm::dvec2(i + 1, j + 1) * ts);
      if (cut.size() >= 3 && signedArea(cut) > kMinCutFraction * ts * ts) fn(i, j, cut);
    }
}

}  // namespace

Atlas buildAtlas(const Scene& scene, double ts, int maxSize) {
  if (!(ts > 0) || !std::isfinite(ts)) fail("--texel-size must be a positive number (got {})", ts);
  const auto& polys = scene.polygons();
  Atlas atlas;
  atlas.texelSize = ts;
  std::vector<ChartShape> shapes;
  for (auto& p : polys) shapes.push_back(chartShape(p, ts));

  // Shelf packing, tallest first; the order is fixed, so the layout is deterministic.
  std::vector<int> order(polys.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return shapes[a].size.y > shapes[b].size.y; });
  double paddedArea = 0;
  int widest = 0;
  for (auto& s : shapes) {
    paddedArea += double(s.size.x + 2 * kGutter) * (s.size.y + 2 * kGutter);
    widest = std::max(widest, s.size.x + 2 * kGutter);
  }
  int width = std::max(widest, int(std::ceil(std::sqrt(paddedArea))));
  if (width > maxSize || paddedArea > double(maxSize) * maxSize)
    fail("texel size {} needs an atlas over {} texels wide (the limit); use --texel-size {:.4g} or larger", ts, maxSize,
         ts * std::sqrt(paddedArea) / maxSize * 1.1);
  atlas.charts.resize(polys.size());
  int x = 0, y = 0, shelf = 0;
  for (int id : order) {
    glm::ivec2 padded = shapes[id].size + 2 * kGutter;
    if (x + padded.x > width) x = 0, y += shelf, shelf = 0;
    Chart& c = atlas.charts[id];
    c.polygon = id;
    c.origin = glm::ivec2(x, y) + kGutter;
    c.size = shapes[id].size;
    c.frame = shapes[id].frame;
    c.corner = shapes[id].corner;
    x += padded.x;
    shelf = std::max(shelf, padded.y);
  }
  atlas.width = width;
  atlas.height = y + shelf;
  if (atlas.height > maxSize)
    fail("texel size {} needs an atlas {} texels high, over the limit {}; use --texel-size {:.4g} or larger", ts,
         atlas.height, maxSize, ts * std::sqrt(double(atlas.height) / maxSize) * 1.1);

  size_t texels = size_t(atlas.width) * atlas.height;
  atlas.positionArea.assign(texels, glm::vec4(0.0f));
  atlas.polygonOf.assign(texels, kNoPolygon);
  for (size_t id = 0; id < polys.size(); ++id) {
    const Chart& c = atlas.charts[id];
    forEachCut(shapes[id], ts, [&](int i, int j, const Poly2& cut) {
      size_t t = size_t(c.origin.y + j) * atlas.width + (c.origin.x + i);
      glm::dvec3 centre = c.frame.lift(centroid(cut));
      atlas.positionArea[t] = glm::vec4(glm::vec3(centre), float(signedArea(cut)));
      atlas.polygonOf[t] = std::uint32_t(id);
      ++atlas.elements;
    });
  }
  return atlas;
}

double texelSizeForElements(const Scene& scene, std::size_t elements) {
  if (elements == 0) fail("--elements must be positive");
  double ts = std::sqrt(scene.totalArea() / double(elements));
  // Partial texels add elements; a few fixed-point steps on the real count settle it.
  for (int iter = 0; iter < 4; ++iter) {
    size_t count = 0;
    for (auto& p : scene.polygons()) forEachCut(chartShape(p, ts), ts, [&](int, int, const Poly2&) { ++count; });
    ts *= std::sqrt(double(count) / double(elements));
  }
  return ts;
}

glm::dvec2 Atlas::atlasCoord(int polygon, const glm::dvec3& p) const {
  const Chart& c = charts[polygon];
  return glm::dvec2(c.origin) + (c.frame.project(p) - c.corner) / texelSize;
}

Poly3 Atlas::elementShape(const Scene& scene, int x, int y) const {
  std::uint32_t id = polygonOf[size_t(y) * width + x];
  if (id == kNoPolygon) return {};
  const Chart& c = charts[id];
  Poly2 poly;
  for (auto& v : scene.polygons()[id].vertices) poly.push_back(c.frame.project(v));
  glm::dvec2 cell(x - c.origin.x, y - c.origin.y);
  Poly3 out;
  for (auto& q : clipToBox(poly, c.corner + cell * texelSize, c.corner + (cell + 1.0) * texelSize))
    out.push_back(c.frame.lift(q));
  return out;
}

glm::vec3 Atlas::sample(const std::vector<glm::vec4>& values, int polygon, glm::dvec2 coord) const {
  auto owned = [&](glm::ivec2 t) {
    return t.x >= 0 && t.y >= 0 && t.x < width && t.y < height && polygonOf[size_t(t.y) * width + t.x] == std::uint32_t(polygon);
  };
  glm::dvec2 c = coord - 0.5;
  glm::ivec2 i0(glm::floor(c));
  glm::dvec2 f = c - glm::dvec2(i0);
  glm::dvec3 sum(0.0);
  double weight = 0;
  for (int k = 0; k < 4; ++k) {
    glm::ivec2 o(k & 1, k >> 1), t = i0 + o;
    double w = (o.x ? f.x : 1 - f.x) * (o.y ? f.y : 1 - f.y);
    if (owned(t)) sum += w * glm::dvec3(values[size_t(t.y) * width + t.x]), weight += w;
  }
  if (weight > 0) return glm::vec3(sum / weight);
  glm::ivec2 centre(glm::floor(coord));
  for (int k = 0; k < 9; ++k) {
    glm::ivec2 t = centre + glm::ivec2(k % 3 - 1, k / 3 - 1);
    if (owned(t)) return glm::vec3(values[size_t(t.y) * width + t.x]);
  }
  return glm::vec3(0.0f);
}

std::vector<ShooterBlock> Atlas::shooterBlocks(int level) const {
  const int b = 1 << level;
  std::vector<ShooterBlock> blocks;
  for (const Chart& c : charts)
    for (int j = 0; j < c.size.y; j += b)
      for (int i = 0; i < c.size.x; i += b) {
        glm::ivec4 rect(c.origin.x + i, c.origin.y + j, std::min(b, c.size.x - i), std::min(b, c.size.y - j));
        bool any = false;
        for (int y = rect.y; y < rect.y + rect.w && !any; ++y)
          for (int x = rect.x; x < rect.x + rect.z && !any; ++x) any = polygonOf[size_t(y) * width + x] != kNoPolygon;
        if (any) blocks.push_back({rect});
      }
  return blocks;
}

}  // namespace hemirad
