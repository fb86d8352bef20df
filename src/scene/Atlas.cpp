#include "src/scene/Atlas.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numeric>
#include <string>

#include "src/base/Error.h"
#include "src/base/MinAreaRect.h"
#include "src/scene/AtlasPacker.h"
#include "src/scene/Charts.h"
#include "src/scene/Clusters.h"
#include "src/scene/SmoothNormals.h"
#include "src/scene/Warnings.h"

namespace hemirad {

namespace {

// Over any GPU's texture size; keeps cell counts far from int overflow (fuzzed slivers).
constexpr double kMaxChartSide = 1 << 20;
// Memory per atlas texel: four GPU textures (centre+area, polygon id, B, dB: 52 bytes, host memory
// on llvmpipe) and the CPU's copies (atlas, emission, read-backs, output images), rounded up.
constexpr double kBytesPerTexel = 128;
// Above this many elements the texel size is not refined by counting cut cells (a clip per cell:
// minutes at 10^8); such counts are over the limits anyway, or within a few % of right.
constexpr std::size_t kMaxCountedElements = std::size_t(1) << 24;

struct ChartShape {
  ChartGroup group;
  ChartMapping map;
  std::vector<Poly2> parts;  // the group's parts in chart coordinates
  glm::dvec2 corner;         // lower-left of the texel grid
  glm::ivec2 size;
  double cellSize = 0;  // the side of its cells (Chart::cellSize)
};

// The seed's frame turned in its plane to the minimum-area rectangle of the chart's outline
// (src/base/MinAreaRect.h), where that saves area: fewer empty cells. A frame already along the
// rectangle (an axis-aligned wall) is kept as it is, bit for bit.
PlaneFrame chartFrame(const ChartGroup& g) {
  PlaneFrame f = planeFrame(g.parts.front(), g.axis);
  std::vector<glm::dvec2> points;
  for (const Poly3& part : g.parts)
    for (auto& v : part) points.push_back(f.project(v));
  const MinAreaRect rect = minAreaRect(points);
  glm::dvec2 lo(1e300), hi(-1e300);
  for (glm::dvec2 q : points) lo = glm::min(lo, q), hi = glm::max(hi, q);
  if (!(rect.area < (1 - 1e-6) * (hi.x - lo.x) * (hi.y - lo.y))) return f;
  const glm::dvec3 u = rect.axis.x * f.u + rect.axis.y * f.v;
  f.u = glm::normalize(u - f.n * glm::dot(u, f.n));
  f.v = glm::cross(f.n, f.u);
  return f;
}

// The grid is centred on the chart's bounds so partial texels are shared by both sides.
ChartShape chartShape(const ChartGroup& g, double ts) {
  ChartShape c;
  c.group = g;
  c.map.planar = g.planar;
  c.map.clustered = g.clustered;
  if (g.uv.empty())
    c.map.frame = chartFrame(g);
  else
    c.map.uv = g.uv;
  glm::dvec2 lo(1e300), hi(-1e300);
  for (std::size_t k = 0; k < g.parts.size(); ++k)
    for (glm::dvec2 q : c.parts.emplace_back(c.map.partInChart(g.parts[k], k)))
      lo = glm::min(lo, q), hi = glm::max(hi, q);
  glm::dvec2 extent = hi - lo;
  glm::dvec2 cells = glm::ceil(extent / ts - 1e-9);
  if (!(cells.x <= kMaxChartSide && cells.y <= kMaxChartSide))
    fail("a polygon {:.4g} long needs over {} texels at texel size {}; use a larger --texel-size",
         std::max(extent.x, extent.y), kMaxChartSide, ts);
  c.size = glm::max(glm::ivec2(cells), glm::ivec2(1));
  c.corner = lo - (glm::dvec2(c.size) * ts - extent) * 0.5;
  c.cellSize = ts;
  return c;
}

// The same grid turned a quarter counter-clockwise in its plane (u' = v, v' = -u): cell (i, j)
// becomes (j, size.x - 1 - i), so the packer may place a chart standing or lying.
void turnQuarter(ChartShape& c) {
  c.map.frame = {c.map.frame.origin, c.map.frame.v, -c.map.frame.u, c.map.frame.n};
  for (Poly2& part : c.parts)
    for (glm::dvec2& q : part) q = glm::dvec2(q.y, -q.x);
  if (c.map.uvMapped()) c.map.uv = c.parts;
  c.corner = glm::dvec2(c.corner.y, -(c.corner.x + c.size.x * c.cellSize));
  c.size = glm::ivec2(c.size.y, c.size.x);
}

template <class Fn>  // fn(i, j, part, cut polygon in plane coordinates)
void forEachCut(const ChartShape& c, Fn&& fn) {
  const double ts = c.cellSize;
  for (std::size_t k = 0; k < c.parts.size(); ++k) {
    glm::ivec2 lo(0), hi = c.size;
    if (c.parts.size() > 1) {  // only the cells under this part's bounds
      glm::dvec2 plo(1e300), phi(-1e300);
      for (auto& q : c.parts[k]) plo = glm::min(plo, q), phi = glm::max(phi, q);
      lo = glm::clamp(glm::ivec2(glm::floor((plo - c.corner) / ts)) - 1, glm::ivec2(0), c.size);
      hi = glm::clamp(glm::ivec2(glm::floor((phi - c.corner) / ts)) + 2, glm::ivec2(0), c.size);
    }
    for (int j = lo.y; j < hi.y; ++j)
      for (int i = lo.x; i < hi.x; ++i) {
        Poly2 cut = clipToBox(c.parts[k], c.corner + glm::dvec2(i, j) * ts, c.corner + glm::dvec2(i + 1, j + 1) * ts);
        if (cut.size() >= 3 && signedArea(cut) > kMinCutFraction * ts * ts) fn(i, j, int(k), cut);
      }
  }
}

// One texel's element, summed over its pieces.
struct ElementSum {
  double area = 0, largest = 0, chartArea = 0;
  glm::dvec3 centre{0.0}, normal{0.0};
  int pieces = 0, polygon = -1;
  glm::dvec3 firstCentre{0.0};
};

using VertexNormals = std::vector<std::vector<glm::dvec3>>;  // SmoothNormals.h

// A UV chart's triangles may not overlap: a texel covered more than once would be two places.
void refuseOverlap(const Scene& scene, const std::vector<ElementSum>& cells, const ChartShape& c, double ts) {
  for (std::size_t t = 0; t < cells.size(); ++t)
    if (cells[t].chartArea > (1 + 1e-6) * ts * ts)
      fail(
          "{}: --uv input: the UV triangles of polygon {}'s chart overlap ({:.3g} times a texel's area in one texel); "
          "lightmap UVs must not overlap",
          scene.path, c.group.polygons.front(), cells[t].chartArea / (ts * ts));
}

// Every cell's element of chart c (row-major over c.size). A curved chart's pieces weigh in the
// smooth normal at their centroid (SmoothNormals.h), a planar one's the plane's.
std::vector<ElementSum> chartElements(const Scene& scene, const ChartShape& c, const VertexNormals& smooth) {
  std::vector<ElementSum> cells(std::size_t(c.size.x) * std::size_t(c.size.y));
  forEachCut(c, [&](int i, int j, int k, const Poly2& cut) {
    const int poly = c.group.partPolygon[std::size_t(k)];
    const ScenePolygon& on = scene.polygons()[std::size_t(poly)];
    const Poly3& part = c.group.parts[std::size_t(k)];
    const double a = c.map.surfaceArea(part, std::size_t(k), on, signedArea(cut));
    const glm::dvec3 centre = c.map.toSurface(part, std::size_t(k), on, centroid(cut));
    ElementSum& e = cells[std::size_t(j) * std::size_t(c.size.x) + std::size_t(i)];
    e.chartArea += signedArea(cut);
    if (e.pieces++ == 0)
      e.firstCentre = centre, e.area = a;
    else
      e.area += a;
    e.centre += a * centre;
    e.normal += a * (c.group.planar ? on.normal : smoothNormalAt(on, smooth[std::size_t(poly)], centre));
    if (a > e.largest) e.largest = a, e.polygon = poly;
  });
  if (c.map.uvMapped() && !c.map.clustered) refuseOverlap(scene, cells, c, c.cellSize);
  return cells;
}

std::size_t countElements(const ChartShape& c) {
  std::size_t n = 0;
  if (c.parts.size() == 1) {
    forEachCut(c, [&](int, int, int, const Poly2&) { ++n; });
    return n;
  }
  std::vector<char> hit(std::size_t(c.size.x) * std::size_t(c.size.y), 0);
  forEachCut(c, [&](int i, int j, int, const Poly2&) {
    char& h = hit[std::size_t(j) * std::size_t(c.size.x) + std::size_t(i)];
    n += h == 0, h = 1;
  });
  return n;
}

// The charts' shapes at texel size ts, small charts clustered (src/scene/Clusters.h) if `cluster`
// (clusters() below).
std::vector<ChartShape> chartShapes(const Scene& scene, const std::vector<ChartGroup>& groups, double ts,
                                    bool cluster) {
  std::vector<ChartShape> shapes;
  std::vector<char> oneCell;
  for (auto& g : groups) {
    shapes.push_back(chartShape(g, ts));
    oneCell.push_back(shapes.back().size == glm::ivec2(1));
  }
  const std::vector<std::vector<int>> sets =
      cluster ? smallChartClusters(scene, groups, oneCell, ts) : std::vector<std::vector<int>>{};
  if (sets.empty()) return shapes;
  std::vector<int> setOf(groups.size(), -1);
  for (std::size_t k = 0; k < sets.size(); ++k)
    for (int m : sets[k]) setOf[std::size_t(m)] = int(k);
  std::vector<ChartShape> out;
  for (std::size_t i = 0; i < groups.size(); ++i) {
    const int k = setOf[i];
    if (k < 0)
      out.push_back(std::move(shapes[i]));
    else if (sets[std::size_t(k)].front() == int(i)) {
      const ChartGroup g = clusterGroup(scene, groups, sets[std::size_t(k)], ts);
      if (!g.parts.empty())
        out.push_back(chartShape(g, ts));
      else  // no member triangle keeps an area in the cell (degenerate input): the members stay charts
        for (int m : sets[std::size_t(k)]) out.push_back(std::move(shapes[std::size_t(m)]));
    }
  }
  return out;
}

struct Layout {
  bool packed = false;           // within maxSize on both sides
  double width = 0, height = 0;  // texels (if not packed: as far as packing got)
  std::vector<glm::ivec2> origins;
  std::vector<char> turned;  // per chart: placed a quarter turned (turnQuarter)
};

// src/scene/AtlasPacker.h, after a cheap bound: charts over maxSize^2 texels are not packed.
Layout pack(const std::vector<ChartShape>& shapes, int maxSize) {
  std::vector<glm::ivec2> sizes;
  double area = 0;
  for (auto& s : shapes) sizes.push_back(s.size), area += double(s.size.x) * s.size.y;
  if (area > double(maxSize) * maxSize) return {false, std::sqrt(area), std::sqrt(area), {}, {}};
  RectLayout r = packAtlasCharts(sizes, maxSize);
  const bool packed = r.width <= maxSize && r.height <= maxSize;
  return {packed, double(r.width), double(r.height), std::move(r.origins), std::move(r.turned)};
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
[[noreturn]] void failOverLimit(const Scene& scene, const std::vector<ChartGroup>& groups, double ts, const Layout& l,
                                int maxSize, double maxBytes, bool cluster) {
  const double texels = l.width * l.height;
  std::string limit = !l.packed ? fmt::format("over the GPU's limit of {} texels a side (GL_MAX_TEXTURE_SIZE)", maxSize)
                                : fmt::format("{} of memory, over the memory limit of {}",
                                              bytesText(texels * kBytesPerTexel), bytesText(maxBytes));
  double fit =
      ts * std::sqrt(std::max({1.0, texels / (double(maxSize) * maxSize), texels * kBytesPerTexel / maxBytes}));
  for (int i = 0; i < 200 && !fits(pack(chartShapes(scene, groups, fit, cluster), maxSize), maxBytes); ++i) fit *= 1.05;
  // Shown to four digits, rounded up: rounded down it may not fit (a unit square at 64 texels).
  const double shown = fit / scene.unitScale, unit = std::pow(10.0, std::floor(std::log10(shown)) - 3);
  fit = std::ceil(shown / unit) * unit * scene.unitScale;
  double elements = scene.totalArea() / (fit * fit);
  double digits = std::pow(10.0, std::floor(std::log10(std::max(elements, 1.0))) - 1);  // two significant
  fail(
      "texel size {:.4g} needs a {:.0f} x {:.0f} texel atlas, {}; use --texel-size {:.4g} or larger (or --elements "
      "{:.0f} "
      "or fewer)",
      ts / scene.unitScale, l.width, l.height, limit, std::ceil(shown / unit) * unit,
      std::max(1.0, std::floor(elements / digits) * digits));
}

// Writes chart c's elements into the atlas.
void cutChart(const Scene& scene, const ChartShape& shape, const Chart& c, const VertexNormals& smooth, Atlas& atlas) {
  const std::vector<ElementSum> cells = chartElements(scene, shape, smooth);
  for (int j = 0; j < c.size.y; ++j)
    for (int i = 0; i < c.size.x; ++i) {
      const ElementSum& e = cells[std::size_t(j) * std::size_t(c.size.x) + std::size_t(i)];
      if (e.pieces == 0) continue;
      const std::size_t t = std::size_t(c.origin.y + j) * std::size_t(atlas.width) + std::size_t(c.origin.x + i);
      // One piece: its own centroid, bit for bit what a chart per polygon gives.
      glm::dvec3 centre = e.pieces == 1 ? e.firstCentre : e.centre / e.area, normal = glm::normalize(e.normal);
      int polygon = e.polygon;
      if (c.clustered) {  // its member nearest the centroid receives for it (Clusters.h)
        polygon = clusterReceiver(scene, c.polygons, centre);
        const ScenePolygon& at = scene.polygons()[std::size_t(polygon)];
        centre = polygonCentroid(at.vertices, at.normal), normal = at.normal;
      }
      atlas.positionArea[t] = glm::vec4(glm::vec3(centre), float(e.area));
      atlas.polygonOf[t] = std::uint32_t(polygon);
      const bool own = e.pieces == 1 && c.planar;  // a polygon's own normal, bit for bit
      atlas.normalOf[t] = glm::vec3(own ? scene.polygons()[std::size_t(e.polygon)].normal : normal);
      ++atlas.elements;
    }
}

// A UV chart's polygons' first parts (Atlas::firstPartOf).
void indexParts(const Chart& c, std::size_t polygons, std::vector<std::uint32_t>& firstPartOf) {
  if (!c.uvMapped()) return;
  firstPartOf.resize(polygons, 0);
  for (std::size_t k = c.parts.size(); k-- > 0;) firstPartOf[std::size_t(c.partPolygon[k])] = std::uint32_t(k);
}

Chart makeChart(const ChartShape& s, glm::ivec2 origin) {
  Chart c;
  c.polygon = s.group.polygons.front();
  static_cast<ChartMapping&>(c) = s.map;
  c.polygons = s.group.polygons;
  c.parts = s.group.parts;
  c.partPolygon = s.group.partPolygon;
  c.origin = origin;
  c.size = s.size;
  c.corner = s.corner;
  c.cellSize = s.cellSize;
  for (std::size_t k = 0; k < c.parts.size(); ++k) c.partBox.push_back(boundingBox(c.partInChart(c.parts[k], k)));
  return c;
}

// Places the packed shapes and cuts their elements (both entries below).
Atlas placeCharts(const Scene& scene, std::vector<ChartShape>& shapes, const Layout& layout, double ts,
                  double chartAngle) {
  Atlas atlas;
  atlas.texelSize = ts;
  for (std::size_t id = 0; id < shapes.size(); ++id)
    if (layout.turned[id]) turnQuarter(shapes[id]);
  atlas.chartOf.assign(scene.polygons().size(), 0);
  for (size_t id = 0; id < shapes.size(); ++id) {
    atlas.charts.push_back(makeChart(shapes[id], layout.origins[id]));
    for (int p : shapes[id].group.polygons) atlas.chartOf[std::size_t(p)] = std::uint32_t(id);
    indexParts(atlas.charts.back(), scene.polygons().size(), atlas.firstPartOf);
  }
  atlas.width = int(layout.width);
  atlas.height = int(layout.height);

  size_t texels = size_t(atlas.width) * atlas.height;
  atlas.positionArea.assign(texels, glm::vec4(0.0f));
  atlas.polygonOf.assign(texels, kNoPolygon);
  atlas.normalOf.assign(texels, glm::vec3(0.0f));
  const bool curved = std::any_of(shapes.begin(), shapes.end(), [](const ChartShape& c) { return !c.group.planar; });
  if (curved) atlas.vertexNormals = smoothVertexNormals(scene, chartAngle);
  for (size_t id = 0; id < shapes.size(); ++id)
    cutChart(scene, shapes[id], atlas.charts[id], atlas.vertexNormals, atlas);
  return atlas;
}

// The atlas of `groups` at texel size ts (buildAtlas's).
Atlas atlasOfGroups(const Scene& scene, const std::vector<ChartGroup>& groups, double ts, int maxSize,
                    std::size_t maxBytes, double chartAngle, bool cluster) {
  const double memory = maxBytes ? double(maxBytes) : hostMemoryBytes();
  // Charts cover at least the scene's area: far over the texture limit, say so before cutting
  // the scene into more cells than any GPU holds.
  if (double least = scene.totalArea() / (ts * ts); least > double(maxSize) * maxSize)
    failOverLimit(scene, groups, ts, {false, std::sqrt(least), std::sqrt(least), {}, {}}, maxSize, memory, cluster);
  std::vector<ChartShape> shapes = chartShapes(scene, groups, ts, cluster);
  Layout layout = pack(shapes, maxSize);
  if (!fits(layout, memory)) failOverLimit(scene, groups, ts, layout, maxSize, memory, cluster);
  Atlas atlas = placeCharts(scene, shapes, layout, ts, chartAngle);
  if (atlas.elements == 0 && !scene.polygons().empty())
    fail("texel size {} leaves no element: every polygon is a sliver under {} of a texel; use a smaller --texel-size",
         ts, kMinCutFraction);
  return atlas;
}

// texelSizeForElements's start: the area's square root, or a sliver's length over `elements`.
double firstTexelSize(const Scene& scene, std::size_t elements) {
  if (elements == 0) fail("--elements must be positive");
  if (scene.polygons().empty()) fail("{}: the scene has no faces with area", scene.path);
  double ts = std::sqrt(scene.totalArea() / double(elements));
  // A thin sliver gets at least one element per texel of its length: start where its length
  // alone gives no more than `elements`, or the first count below walks billions of cells.
  for (auto& p : scene.polygons())
    for (auto& v : p.vertices) ts = std::max(ts, glm::length(v - p.vertices.front()) / double(elements));
  return ts;
}

// Partial texels add elements; a few fixed-point steps on the real count of `groups` settle it.
double settledTexelSize(const Scene& scene, const std::vector<ChartGroup>& groups, std::size_t elements, double ts,
                        bool cluster) {
  for (int iter = 0; iter < 4 && elements <= kMaxCountedElements; ++iter) {
    size_t count = 0;
    for (auto& s : chartShapes(scene, groups, ts, cluster)) count += countElements(s);
    if (count == 0) break;  // only slivers: buildAtlas says so
    ts *= std::sqrt(double(count) / double(elements));
  }
  return ts;
}

// Small charts are clustered (Clusters.h) but where a chart per polygon is asked for, or the
// input's lightmap UVs, whose islands are the user's.
bool clusters(double chartAngle, UvSource uv) { return chartAngle != kPolygonCharts && uv != UvSource::Input; }

}  // namespace

Atlas buildAtlas(const Scene& scene, double ts, int maxSize, std::size_t maxBytes, double chartAngle, UvSource uv) {
  if (!(ts > 0) || !std::isfinite(ts)) fail("--texel-size must be a positive number (got {})", ts);
  return atlasOfGroups(scene, chartGroups(scene, chartAngle, uv), ts, maxSize, maxBytes, chartAngle,
                       clusters(chartAngle, uv));
}

Atlas buildAtlas(const Scene& scene, const Discretisation& d, int maxSize, std::size_t maxBytes) {
  if (d.texelSize) return buildAtlas(scene, chooseTexelSize(scene, d), maxSize, maxBytes, d.chartAngle, d.uv);
  const std::size_t elements = d.elements.value_or(Discretisation::kDefaultElements);
  const double first = firstTexelSize(scene, elements);
  const std::vector<ChartGroup> groups = chartGroups(scene, d.chartAngle, d.uv);
  const double ts = settledTexelSize(scene, groups, elements, first, clusters(d.chartAngle, d.uv));
  if (!(ts > 0) || !std::isfinite(ts)) fail("--texel-size must be a positive number (got {})", ts);
  Atlas atlas = atlasOfGroups(scene, groups, ts, maxSize, maxBytes, d.chartAngle, clusters(d.chartAngle, d.uv));
  // Every chart holds at least one element, and small charts share one only within an object,
  // a material and a facing (Clusters.h): many small parts unlike each other cannot go lower.
  if (double(atlas.elements) > Discretisation::kElementsOver * double(elements))
    warn(
        fmt::format("{} elements for --elements {}: each of the {} charts holds at least one (small parts share "
                    "elements only within one object, material and facing)",
                    withThousands(atlas.elements), withThousands(elements), withThousands(atlas.charts.size())));
  return atlas;
}

Atlas buildAtlas(const Scene& scene, const std::vector<ChartSpec>& specs, double texelSize, int maxSize,
                 std::size_t maxBytes, double chartAngle) {
  std::vector<ChartShape> shapes;
  for (const ChartSpec& spec : specs) {
    ChartShape& c = shapes.emplace_back();
    c.group = spec.group, c.corner = spec.corner, c.size = spec.size, c.cellSize = spec.cellSize;
    c.map.frame = spec.frame, c.map.planar = spec.group.planar, c.map.uv = spec.group.uv;
    c.map.clustered = spec.group.clustered;
    for (std::size_t k = 0; k < spec.group.parts.size(); ++k)
      c.parts.push_back(c.map.partInChart(spec.group.parts[k], k));
  }
  const double memory = maxBytes ? double(maxBytes) : hostMemoryBytes();
  Layout layout = pack(shapes, maxSize);
  if (!fits(layout, memory))
    fail(
        "the adaptive layout needs a {:.0f} x {:.0f} texel atlas, over the GPU's limit of {} texels a side or the "
        "memory's; use fewer --elements, a larger --split-gradient or a smaller --leaf-depth",
        layout.width, layout.height, maxSize);
  return placeCharts(scene, shapes, layout, texelSize, chartAngle);
}

double texelSizeForElements(const Scene& scene, std::size_t elements, double chartAngle, UvSource uv) {
  const double ts = firstTexelSize(scene, elements);
  if (elements > kMaxCountedElements) return ts;
  return settledTexelSize(scene, chartGroups(scene, chartAngle, uv), elements, ts, clusters(chartAngle, uv));
}

glm::dvec2 Atlas::chartCoord(int polygon, const glm::dvec3& p) const {
  const Chart& c = charts[chartOf[std::size_t(polygon)]];
  if (!c.uvMapped()) return c.frame.project(p);
  std::size_t best = firstPartOf[std::size_t(polygon)];  // the polygon's triangle holding p (or nearest)
  double fit = -1e300;
  for (std::size_t k = best; k < c.parts.size() && c.partPolygon[k] == polygon; ++k)
    if (const double f = c.inside(c.parts[k], k, p); f > fit) fit = f, best = k;
  return c.toChart(c.parts[best], best, p);
}

glm::dvec2 Atlas::atlasCoord(int polygon, const glm::dvec3& p) const {
  const Chart& c = charts[chartOf[std::size_t(polygon)]];
  return glm::dvec2(c.origin) + (chartCoord(polygon, p) - c.corner) / c.cellSize;
}

std::vector<Poly3> Atlas::elementShape(const Scene& scene, int x, int y) const {
  if (polygonOf[size_t(y) * width + x] == kNoPolygon) return {};
  return blockShape(scene, glm::ivec4(x, y, 1, 1));
}

namespace {
// Pieces' areas and their hull's agree to rounding when they tile it; a gap or notch of a
// millionth of the block is not rounding.
constexpr double kTilingTolerance = 1e-6;
}  // namespace

std::uint32_t Atlas::chartUnder(glm::ivec4 rect) const {
  std::uint32_t chart = kNoPolygon;
  for (int y = rect.y; y < rect.y + rect.w && chart == kNoPolygon; ++y)
    for (int x = rect.x; x < rect.x + rect.z && chart == kNoPolygon; ++x) chart = chartAt(size_t(y) * width + x);
  return chart;
}

std::vector<Poly3> Atlas::blockShape(const Scene& scene, glm::ivec4 rect, std::vector<std::uint32_t>* polygons) const {
  const std::uint32_t chart = chartUnder(rect);
  if (chart == kNoPolygon) return {};
  const Chart& c = charts[chart];
  glm::dvec2 lo(rect.x - c.origin.x, rect.y - c.origin.y), hi = lo + glm::dvec2(rect.z, rect.w);
  std::vector<Poly3> out;
  const glm::dvec2 boxLo = c.corner + lo * c.cellSize, boxHi = c.corner + hi * c.cellSize;
  for (std::size_t k = 0; k < c.parts.size(); ++k) {
    if (!c.partBox[k].meets(boxLo, boxHi)) continue;  // most of a large chart's parts
    const Poly2 part = c.partInChart(c.parts[k], k);
    Poly2 cut = clipToBox(part, boxLo, boxHi);
    if (cut.size() < 3 || signedArea(cut) <= kMinCutFraction * c.cellSize * c.cellSize) continue;
    const ScenePolygon& on = scene.polygons()[std::size_t(c.partPolygon[k])];
    Poly3& piece = out.emplace_back();
    for (auto& q : cut) piece.push_back(c.toSurface(c.parts[k], k, on, q));
    if (polygons) polygons->push_back(std::uint32_t(c.partPolygon[k]));
  }
  return out;
}

std::vector<Poly3> Atlas::blockOutline(const Scene& scene, glm::ivec4 rect) const {
  std::vector<Poly3> pieces = blockShape(scene, rect);
  if (pieces.size() < 2) return pieces;
  const Chart& c = charts[chartUnder(rect)];
  if (!c.planar || c.uvMapped()) return pieces;
  // Convex pieces that do not overlap tile a convex region exactly when their areas sum to their hull's.
  std::vector<glm::dvec2> corners;
  double sum = 0;
  for (const Poly3& piece : pieces) {
    Poly2 flat;
    for (const glm::dvec3& p : piece) flat.push_back(c.frame.project(p));
    sum += std::abs(signedArea(flat));
    corners.insert(corners.end(), flat.begin(), flat.end());
  }
  const Poly2 hull = convexHull(std::move(corners));
  if (hull.size() < 3 || std::abs(signedArea(hull) - sum) > kTilingTolerance * sum) return pieces;
  Poly3 outline;  // counter-clockwise in the frame, as blockShape's cuts are
  for (const glm::dvec2& q : hull) outline.push_back(c.frame.lift(q));
  return {outline};
}

glm::vec3 Atlas::sample(const std::vector<glm::vec4>& values, int polygon, glm::dvec2 coord) const {
  const std::uint32_t chart = chartOf[std::size_t(polygon)];
  auto owned = [&](glm::ivec2 t) {
    return t.x >= 0 && t.y >= 0 && t.x < width && t.y < height && chartAt(size_t(t.y) * width + t.x) == chart;
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

std::vector<ShooterBlock> Atlas::shooterBlocks(const std::vector<int>& chartLevel) const {
  std::vector<ShooterBlock> blocks;
  for (std::size_t id = 0; id < charts.size(); ++id) {
    const Chart& c = charts[id];
    const int b = 1 << chartLevel[id];
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

std::uint64_t Atlas::layoutHash() const {
  std::uint64_t h = 1469598103934665603ull;  // FNV-1a over the values' bytes
  auto add = [&](const auto& value) {
    const auto* bytes = reinterpret_cast<const unsigned char*>(&value);
    for (std::size_t i = 0; i < sizeof(value); ++i) h = (h ^ bytes[i]) * 1099511628211ull;
  };
  for (const Chart& c : charts) {
    add(c.origin), add(c.size), add(c.frame.u), add(c.frame.v), add(c.corner);
    for (const Poly2& t : c.uv)
      for (glm::dvec2 q : t) add(q);
    if (c.cellSize != texelSize) add(c.cellSize);  // refined leaves; uniform hashes are as before
  }
  return h;
}

double chooseTexelSize(const Scene& scene, const Discretisation& d) {
  if (d.texelSize) return *d.texelSize * scene.unitScale;  // given in the file's units
  return texelSizeForElements(scene, d.elements.value_or(Discretisation::kDefaultElements), d.chartAngle, d.uv);
}

}  // namespace hemirad
