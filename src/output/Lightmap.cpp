#include "src/output/Lightmap.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "src/base/Error.h"
#include "src/output/ChartPacker.h"

namespace hemirad {

namespace {

// Per axis: the chart is one cell across there, so its lightmap coordinate is the cells' centre
// line and it needs no gutter on that axis (Lightmap.h).
glm::bvec2 oneCellAcross(const Chart& c) { return glm::equal(c.size, glm::ivec2(1)); }

// Chart-local cell coordinates where coord() does not clamp them: [0.5, size - 0.5] on an axis
// without gutter (a point on a one-cell axis), everything elsewhere.
void unclampedCells(const Chart& c, glm::ivec2 gutter, glm::dvec2& lo, glm::dvec2& hi) {
  constexpr double kAll = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 2; ++k) {
    lo[k] = gutter[k] ? -kAll : 0.5;
    hi[k] = gutter[k] ? kAll : c.size[k] - 0.5;
  }
}

// Fills every empty texel of one chart's padded rectangle (size `size`, `value` per texel,
// `filled` marks) level by level outward from the elements: each takes the mean of its filled
// edge neighbours, else of its filled corner neighbours, so the nearest elements' B reaches it.
void dilate(glm::ivec2 size, std::vector<glm::vec3>& value, std::vector<char>& filled) {
  auto at = [&](int x, int y) { return std::size_t(y) * std::size_t(size.x) + std::size_t(x); };
  auto inside = [&](int x, int y) { return x >= 0 && y >= 0 && x < size.x && y < size.y; };
  static constexpr int kEdge[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
  static constexpr int kCorner[4][2] = {{1, 1}, {-1, 1}, {1, -1}, {-1, -1}};
  std::vector<glm::ivec2> frontier, next;
  for (int y = 0; y < size.y; ++y)
    for (int x = 0; x < size.x; ++x)
      if (filled[at(x, y)]) frontier.push_back({x, y});
  std::vector<char> queued(filled);
  while (!frontier.empty()) {
    next.clear();
    for (glm::ivec2 t : frontier)
      for (int k = 0; k < 8; ++k) {
        const int* d = k < 4 ? kEdge[k] : kCorner[k - 4];
        const int x = t.x + d[0], y = t.y + d[1];
        if (inside(x, y) && !queued[at(x, y)]) queued[at(x, y)] = 1, next.push_back({x, y});
      }
    std::sort(next.begin(), next.end(), [](glm::ivec2 a, glm::ivec2 b) { return a.y != b.y ? a.y < b.y : a.x < b.x; });
    std::vector<glm::vec3> values(next.size());
    for (std::size_t i = 0; i < next.size(); ++i)
      for (const auto* ring : {kEdge, kCorner}) {
        glm::vec3 sum(0.0f);
        int n = 0;
        for (int k = 0; k < 4; ++k) {
          const int x = next[i].x + ring[k][0], y = next[i].y + ring[k][1];
          if (inside(x, y) && filled[at(x, y)]) sum += value[at(x, y)], ++n;
        }
        if (n) {
          values[i] = sum / float(n);
          break;
        }
      }
    for (std::size_t i = 0; i < next.size(); ++i)
      value[at(next[i].x, next[i].y)] = values[i], filled[at(next[i].x, next[i].y)] = 1;
    std::swap(frontier, next);
  }
}

// Copies chart `c`'s elements into the lightmap at its origin (transposed if so placed) and, if
// asked, dilates them over its cells without element and its gutter; what falls outside the
// image (the gutter on the border) is left out.
void fillChart(const Atlas& atlas, const std::vector<glm::vec4>& B, std::size_t chart, bool dilateGutter,
               Lightmap& map) {
  const Chart& c = atlas.charts[chart];
  const glm::ivec2 gutter = map.gutters[chart];
  const glm::ivec2 size = c.size + 2 * gutter;
  std::vector<glm::vec3> value(std::size_t(size.x) * size.y, glm::vec3(0.0f));
  std::vector<char> filled(value.size(), 0);
  for (int j = 0; j < c.size.y; ++j)
    for (int i = 0; i < c.size.x; ++i) {
      const std::size_t t = std::size_t(c.origin.y + j) * atlas.width + std::size_t(c.origin.x + i);
      if (atlas.chartAt(t) != std::uint32_t(chart)) continue;
      const std::size_t local = std::size_t(j + gutter.y) * size.x + std::size_t(i + gutter.x);
      value[local] = glm::vec3(B[t]);
      filled[local] = 1;
      ++map.elements;
    }
  if (dilateGutter) dilate(size, value, filled);
  const bool transposed = map.transposed[chart];
  const glm::ivec2 corner = map.origins[chart] - (transposed ? glm::ivec2(gutter.y, gutter.x) : gutter);
  for (int y = 0; y < size.y; ++y)
    for (int x = 0; x < size.x; ++x) {
      const glm::ivec2 t = corner + (transposed ? glm::ivec2(y, x) : glm::ivec2(x, y));
      if (t.x < 0 || t.y < 0 || t.x >= map.width || t.y >= map.height) continue;
      map.rgb[std::size_t(t.y) * map.width + std::size_t(t.x)] = value[std::size_t(y) * size.x + x];
      ++map.chartTexels;
    }
}

// `piece` split along atlas axis k's line at `line`: the parts below and above it (each empty
// where the piece lies on the other side). Vertices on the line go to both.
void split(const SurfacePiece& piece, int k, double line, SurfacePiece& below, SurfacePiece& above) {
  below.clear(), above.clear();
  for (std::size_t i = 0; i < piece.size(); ++i) {
    const SurfacePoint& a = piece[i];
    const SurfacePoint& b = piece[(i + 1) % piece.size()];
    const double da = a.atlas[k] - line, db = b.atlas[k] - line;
    if (da <= 0) below.push_back(a);
    if (da >= 0) above.push_back(a);
    if ((da < 0 && db > 0) || (da > 0 && db < 0)) {
      // From the edge's lower end: a neighbouring piece crossing it the other way gets the same point.
      const SurfacePoint& l = da < 0 ? a : b;
      const SurfacePoint& h = da < 0 ? b : a;
      const double t = (line - l.atlas[k]) / (h.atlas[k] - l.atlas[k]);
      SurfacePoint m{glm::mix(l.position, h.position, t), glm::mix(l.atlas, h.atlas, t), glm::mix(l.plane, h.plane, t)};
      m.atlas[k] = line;  // exactly on it: both sides clamp it alike
      below.push_back(m), above.push_back(m);
    }
  }
  if (below.size() < 3) below.clear();
  if (above.size() < 3) above.clear();
}

}  // namespace

std::vector<SurfacePiece> Lightmap::affinePieces(const Atlas& atlas, int polygon, const SurfacePiece& t) const {
  glm::dvec2 lo, hi;
  unclamped(atlas, polygon, lo, hi);
  std::vector<SurfacePiece> pieces{t}, next;
  SurfacePiece below, above;
  for (int k = 0; k < 2; ++k) {
    if (!(lo[k] < hi[k]) || !std::isfinite(lo[k])) continue;  // no clamp, or a point: affine already
    for (double line : {lo[k], hi[k]}) {
      next.clear();
      for (const SurfacePiece& p : pieces) {
        split(p, k, line, below, above);
        if (!below.empty()) next.push_back(below);
        if (!above.empty()) next.push_back(above);
      }
      std::swap(pieces, next);
    }
  }
  return pieces;
}

void Lightmap::unclamped(const Atlas& atlas, int polygon, glm::dvec2& lo, glm::dvec2& hi) const {
  const std::size_t chart = atlas.chartOf[std::size_t(polygon)];
  unclampedCells(atlas.charts[chart], gutters[chart], lo, hi);
  lo += glm::dvec2(atlas.charts[chart].origin), hi += glm::dvec2(atlas.charts[chart].origin);
}

glm::dvec2 Lightmap::coord(const Atlas& atlas, int polygon, glm::dvec2 atlasCoord) const {
  const std::size_t chart = atlas.chartOf[std::size_t(polygon)];
  const Chart& c = atlas.charts[chart];
  glm::dvec2 lo, hi;
  unclampedCells(c, gutters[chart], lo, hi);
  const glm::dvec2 local = glm::clamp(atlasCoord - glm::dvec2(c.origin), lo, hi);
  return (transposed[chart] ? glm::dvec2(local.y, local.x) : local) + glm::dvec2(origins[chart]);
}

glm::dvec2 Lightmap::uv(const Atlas& atlas, int polygon, glm::dvec2 atlasCoord) const {
  return coord(atlas, polygon, atlasCoord) / glm::dvec2(width, height);
}

Lightmap buildLightmap(const Atlas& atlas, const std::vector<glm::vec4>& B, const LightmapOptions& options) {
  if (B.size() != atlas.polygonOf.size())
    fail("lightmap: {} radiosity texels for a {} texel atlas", B.size(), atlas.polygonOf.size());
  const int g = std::max(0, options.gutter);
  Lightmap map;
  std::vector<glm::ivec2> padded;
  bool everyGutter = true;  // only then may the packer cut the border's gutters away
  for (const Chart& c : atlas.charts) {
    map.gutters.push_back(glm::mix(glm::ivec2(g), glm::ivec2(0), oneCellAcross(c)));
    padded.push_back(c.size + 2 * map.gutters.back());
    everyGutter = everyGutter && map.gutters.back() == glm::ivec2(g);
  }
  const ChartLayout layout = packCharts(padded, everyGutter ? g : 0, options.maxAspect);
  map.width = layout.width, map.height = layout.height, map.gutter = g, map.transposed = layout.transposed;
  for (std::size_t c = 0; c < atlas.charts.size(); ++c) {
    const glm::ivec2 gutter = map.gutters[c];  // the chart's own axes; the layout may have turned it
    map.origins.push_back(layout.corners[c] + (map.transposed[c] ? glm::ivec2(gutter.y, gutter.x) : gutter));
  }
  map.rgb.assign(std::size_t(map.width) * map.height, glm::vec3(0.0f));
  for (std::size_t c = 0; c < atlas.charts.size(); ++c) fillChart(atlas, B, c, options.dilate, map);
  return map;
}

}  // namespace hemirad
