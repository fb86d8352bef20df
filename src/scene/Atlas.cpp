#include "src/scene/Atlas.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numeric>
#include <string>

#include "src/base/Error.h"

namespace hemirad {

namespace {

constexpr int kGutter = 1;
// Cuts smaller than this fraction of a texel are numerical slivers, not elements.
constexpr double kMinCutFraction = 1e-9;
// Over any GPU's texture size; keeps cell counts far from int overflow (fuzzed slivers).
constexpr double kMaxChartSide = 1 << 20;
// Memory per atlas texel: four GPU textures (centre+area, polygon id, B, dB: 52 bytes, host memory
// on llvmpipe) and the CPU's copies (atlas, emission, read-backs, output images), rounded up.
constexpr double kBytesPerTexel = 128;
// Above this many elements the texel size is not refined by counting cut cells (a clip per cell:
// minutes at 10^8); such counts are over the limits anyway, or within a few % of right.
constexpr std::size_t kMaxCountedElements = std::size_t(1) << 24;

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
  glm::dvec2 cells = glm::ceil(extent / ts - 1e-9);
  if (!(cells.x <= kMaxChartSide && cells.y <= kMaxChartSide))
    fail("a polygon {:.4g} long needs over {} texels at texel size {}; use a larger --texel-size",
         std::max(extent.x, extent.y), kMaxChartSide, ts);
  c.size = glm::max(glm::ivec2(cells), glm::ivec2(1));
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

std::vector<ChartShape> chartShapes(const Scene& scene, double ts) {
  std::vector<ChartShape> shapes;
  for (auto& p : scene.polygons()) shapes.push_back(chartShape(p, ts));
  return shapes;
}

struct Layout {
  bool packed = false;           // within maxSize on both sides
  double width = 0, height = 0;  // texels (if not packed: as far as packing got)
  std::vector<glm::ivec2> origins;
};

// Shelf packing, tallest first, into an atlas about as wide as high; the order is fixed, so the
// layout is deterministic. Stops as soon as a side would exceed maxSize.
Layout pack(const std::vector<ChartShape>& shapes, int maxSize) {
  Layout l;
  double paddedArea = 0, widest = 0;
  for (auto& s : shapes) {
    paddedArea += double(s.size.x + 2 * kGutter) * (s.size.y + 2 * kGutter);
    widest = std::max(widest, double(s.size.x + 2 * kGutter));
  }
  l.width = std::max(widest, std::ceil(std::sqrt(paddedArea)));
  l.height = std::ceil(paddedArea / std::max(l.width, 1.0));
  if (l.width > maxSize || paddedArea > double(maxSize) * maxSize) return l;
  std::vector<int> order(shapes.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return shapes[a].size.y > shapes[b].size.y; });
  l.origins.resize(shapes.size());
  int width = int(l.width), x = 0, y = 0, shelf = 0;
  for (int id : order) {
    glm::ivec2 padded = shapes[id].size + 2 * kGutter;
    if (x + padded.x > width) x = 0, y += shelf, shelf = 0;
    if (y + padded.y > maxSize) return l.height = y + padded.y, l;
    l.origins[id] = glm::ivec2(x, y) + kGutter;
    x += padded.x;
    shelf = std::max(shelf, padded.y);
  }
  l.height = y + shelf;
  l.packed = true;
  return l;
}

bool fits(const Layout& l, double maxBytes) { return l.packed && l.width * l.height * kBytesPerTexel <= maxBytes; }

std::string bytesText(double b) {
  return b >= double(1 << 30) ? fmt::format("{:.1f} GiB", b / (1 << 30)) : fmt::format("{:.1f} MiB", b / (1 << 20));
}

// This machine's memory (or its cgroup's limit, if less): on llvmpipe, the GPU's memory too.
double hostMemoryBytes() {
  double bytes = double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGE_SIZE)), limit = 0;
  if (std::ifstream cgroup("/sys/fs/cgroup/memory.max"); cgroup >> limit && limit > 0) bytes = std::min(bytes, limit);
  return bytes;
}

// The error for an atlas over a limit, with the texel size that fits (found by packing, 5 % steps).
[[noreturn]] void failOverLimit(const Scene& scene, double ts, const Layout& l, int maxSize, double maxBytes) {
  const double texels = l.width * l.height;
  std::string limit = !l.packed ? fmt::format("over the GPU's limit of {} texels a side (GL_MAX_TEXTURE_SIZE)", maxSize)
                                : fmt::format("{} of memory, over the memory limit of {}",
                                              bytesText(texels * kBytesPerTexel), bytesText(maxBytes));
  double fit = ts * std::sqrt(std::max({1.0, texels / (double(maxSize) * maxSize), texels * kBytesPerTexel / maxBytes}));
  for (int i = 0; i < 200 && !fits(pack(chartShapes(scene, fit), maxSize), maxBytes); ++i) fit *= 1.05;
  double elements = scene.totalArea() / (fit * fit);
  double digits = std::pow(10.0, std::floor(std::log10(std::max(elements, 1.0))) - 1);  // two significant
  fail("texel size {:.4g} needs a {:.0f} x {:.0f} texel atlas, {}; use --texel-size {:.4g} or larger (or --elements {:.0f} "
       "or fewer)",
       ts / scene.unitScale, l.width, l.height, limit, fit / scene.unitScale,
       std::max(1.0, std::floor(elements / digits) * digits));
}

}  // namespace

Atlas buildAtlas(const Scene& scene, double ts, int maxSize, std::size_t maxBytes) {
  if (!(ts > 0) || !std::isfinite(ts)) fail("--texel-size must be a positive number (got {})", ts);
  const auto& polys = scene.polygons();
  Atlas atlas;
  atlas.texelSize = ts;
  const double memory = maxBytes ? double(maxBytes) : hostMemoryBytes();
  // Charts cover at least the scene's area: far over the texture limit, say so before cutting
  // the scene into more cells than any GPU holds.
  if (double least = scene.totalArea() / (ts * ts); least > double(maxSize) * maxSize)
    failOverLimit(scene, ts, {false, std::sqrt(least), std::sqrt(least), {}}, maxSize, memory);
  std::vector<ChartShape> shapes = chartShapes(scene, ts);
  Layout layout = pack(shapes, maxSize);
  if (!fits(layout, memory)) failOverLimit(scene, ts, layout, maxSize, memory);
  atlas.charts.resize(polys.size());
  for (size_t id = 0; id < polys.size(); ++id) {
    Chart& c = atlas.charts[id];
    c.polygon = int(id);
    c.origin = layout.origins[id];
    c.size = shapes[id].size;
    c.frame = shapes[id].frame;
    c.corner = shapes[id].corner;
  }
  atlas.width = int(layout.width);
  atlas.height = int(layout.height);

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
  if (atlas.elements == 0 && !polys.empty())
    fail("texel size {} leaves no element: every polygon is a sliver under {} of a texel; use a smaller --texel-size",
         ts, kMinCutFraction);
  return atlas;
}

double texelSizeForElements(const Scene& scene, std::size_t elements) {
  if (elements == 0) fail("--elements must be positive");
  if (scene.polygons().empty()) fail("{}: the scene has no faces with area", scene.path);
  double ts = std::sqrt(scene.totalArea() / double(elements));
  // A thin sliver gets at least one element per texel of its length: start where its length
  // alone gives no more than `elements`, or the first count below walks billions of cells.
  for (auto& p : scene.polygons())
    for (auto& v : p.vertices) ts = std::max(ts, glm::length(v - p.vertices.front()) / double(elements));
  // Partial texels add elements; a few fixed-point steps on the real count settle it.
  for (int iter = 0; iter < 4 && elements <= kMaxCountedElements; ++iter) {
    size_t count = 0;
    for (auto& p : scene.polygons()) forEachCut(chartShape(p, ts), ts, [&](int, int, const Poly2&) { ++count; });
    if (count == 0) break;  // only slivers: buildAtlas says so
    ts *= std::sqrt(double(count) / double(elements));
  }
  return ts;
}

glm::dvec2 Atlas::atlasCoord(int polygon, const glm::dvec3& p) const {
  const Chart& c = charts[polygon];
  return glm::dvec2(c.origin) + (c.frame.project(p) - c.corner) / texelSize;
}

Poly3 Atlas::elementShape(const Scene& scene, int x, int y) const {
  if (polygonOf[size_t(y) * width + x] == kNoPolygon) return {};
  return blockShape(scene, glm::ivec4(x, y, 1, 1));
}

Poly3 Atlas::blockShape(const Scene& scene, glm::ivec4 rect) const {
  std::uint32_t id = kNoPolygon;
  for (int y = rect.y; y < rect.y + rect.w && id == kNoPolygon; ++y)
    for (int x = rect.x; x < rect.x + rect.z && id == kNoPolygon; ++x) id = polygonOf[size_t(y) * width + x];
  if (id == kNoPolygon) return {};
  const Chart& c = charts[id];
  Poly2 poly;
  for (auto& v : scene.polygons()[id].vertices) poly.push_back(c.frame.project(v));
  glm::dvec2 lo(rect.x - c.origin.x, rect.y - c.origin.y), hi = lo + glm::dvec2(rect.z, rect.w);
  Poly3 out;
  for (auto& q : clipToBox(poly, c.corner + lo * texelSize, c.corner + hi * texelSize)) out.push_back(c.frame.lift(q));
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
  return shooterBlocks(std::vector<int>(charts.size(), level));
}

std::vector<ShooterBlock> Atlas::shooterBlocks(const std::vector<int>& polygonLevel) const {
  std::vector<ShooterBlock> blocks;
  for (const Chart& c : charts) {
    const int b = 1 << polygonLevel[size_t(c.polygon)];
    for (int j = 0; j < c.size.y; j += b)
      for (int i = 0; i < c.size.x; i += b) {
        glm::ivec4 rect(c.origin.x + i, c.origin.y + j, std::min(b, c.size.x - i), std::min(b, c.size.y - j));
        bool any = false;
        for (int y = rect.y; y < rect.y + rect.w && !any; ++y)
          for (int x = rect.x; x < rect.x + rect.z && !any; ++x) any = polygonOf[size_t(y) * width + x] != kNoPolygon;
        if (any) blocks.push_back({rect});
      }
  }
  return blocks;
}

double chooseTexelSize(const Scene& scene, const Discretisation& d) {
  if (d.texelSize) return *d.texelSize * scene.unitScale;  // given in the file's units
  return texelSizeForElements(scene, d.elements.value_or(Discretisation::kDefaultElements));
}

}  // namespace hemirad
