#include "src/output/Lightmap.h"

#include <stb_rect_pack.h>

#include <algorithm>
#include <cmath>

#include "src/base/Error.h"

namespace hemirad {

namespace {

struct Packed {
  int width = 0, height = 0;
  std::vector<glm::ivec2> origins;  // of the padded rectangles
};

// stb_rect_pack's skyline packer into a strip `width` wide; the height is what it used.
Packed packStrip(const std::vector<glm::ivec2>& sizes, int width, int heuristic) {
  std::vector<stbrp_rect> rects(sizes.size());
  for (std::size_t i = 0; i < sizes.size(); ++i) rects[i] = {int(i), sizes[i].x, sizes[i].y, 0, 0, 0};
  std::vector<stbrp_node> nodes(std::size_t(width) + 1);
  stbrp_context context;
  stbrp_init_target(&context, width, 1 << 30, nodes.data(), int(nodes.size()));
  stbrp_setup_heuristic(&context, heuristic);
  if (!stbrp_pack_rects(&context, rects.data(), int(rects.size()))) return {};
  Packed p{width, 0, std::vector<glm::ivec2>(sizes.size())};
  for (const stbrp_rect& r : rects) {
    p.origins[std::size_t(r.id)] = {r.x, r.y};
    p.height = std::max(p.height, r.y + r.h);
  }
  return p;
}

// The strip width and skyline heuristic with the least area, over widths around the square root
// of the charts' area; fixed candidates, so the layout is deterministic.
Packed pack(const std::vector<glm::ivec2>& sizes) {
  double area = 0;
  int widest = 1;
  for (glm::ivec2 s : sizes) area += double(s.x) * s.y, widest = std::max(widest, s.x);
  const int side = std::max(widest, int(std::ceil(std::sqrt(area))));
  Packed best;
  for (int step = 0; step <= 16; ++step)
    for (int heuristic : {STBRP_HEURISTIC_Skyline_BL_sortHeight, STBRP_HEURISTIC_Skyline_BF_sortHeight}) {
      const int width = std::max(widest, int(std::ceil(side * (0.8 + 0.05 * step))));
      Packed p = packStrip(sizes, width, heuristic);
      if (p.width && (!best.width || double(p.width) * p.height < double(best.width) * best.height)) best = std::move(p);
    }
  if (!best.width) fail("the lightmap's charts do not pack");  // stb packs any set into an unbounded strip
  return best;
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
    for (std::size_t i = 0; i < next.size(); ++i) value[at(next[i].x, next[i].y)] = values[i], filled[at(next[i].x, next[i].y)] = 1;
    std::swap(frontier, next);
  }
}

// Copies chart `c`'s elements into the lightmap at `origin` and, if asked, dilates them over
// its cells without element and its gutter.
void fillChart(const Atlas& atlas, const std::vector<glm::vec4>& B, const Chart& c, int gutter, bool dilateGutter,
               Lightmap& map) {
  const glm::ivec2 size = c.size + 2 * gutter;
  std::vector<glm::vec3> value(std::size_t(size.x) * size.y, glm::vec3(0.0f));
  std::vector<char> filled(value.size(), 0);
  for (int j = 0; j < c.size.y; ++j)
    for (int i = 0; i < c.size.x; ++i) {
      const std::size_t t = std::size_t(c.origin.y + j) * atlas.width + std::size_t(c.origin.x + i);
      if (atlas.polygonOf[t] != std::uint32_t(c.polygon)) continue;
      const std::size_t local = std::size_t(j + gutter) * size.x + std::size_t(i + gutter);
      value[local] = glm::vec3(B[t]);
      filled[local] = 1;
      ++map.elements;
    }
  if (dilateGutter) dilate(size, value, filled);
  const glm::ivec2 corner = map.origins[std::size_t(c.polygon)] - gutter;
  for (int y = 0; y < size.y; ++y)
    for (int x = 0; x < size.x; ++x)
      map.rgb[std::size_t(corner.y + y) * map.width + std::size_t(corner.x + x)] = value[std::size_t(y) * size.x + x];
}

}  // namespace

glm::dvec2 Lightmap::coord(const Atlas& atlas, int polygon, glm::dvec2 atlasCoord) const {
  return atlasCoord - glm::dvec2(atlas.charts[std::size_t(polygon)].origin) + glm::dvec2(origins[std::size_t(polygon)]);
}

glm::dvec2 Lightmap::uv(const Atlas& atlas, int polygon, glm::dvec2 atlasCoord) const {
  return coord(atlas, polygon, atlasCoord) / glm::dvec2(width, height);
}

Lightmap buildLightmap(const Atlas& atlas, const std::vector<glm::vec4>& B, const LightmapOptions& options) {
  if (B.size() != atlas.polygonOf.size()) fail("lightmap: {} radiosity texels for a {} texel atlas", B.size(), atlas.polygonOf.size());
  const int g = std::max(0, options.gutter);
  std::vector<glm::ivec2> padded;
  std::size_t chartTexels = 0;
  for (const Chart& c : atlas.charts) {
    padded.push_back(c.size + 2 * g);
    chartTexels += std::size_t(padded.back().x) * std::size_t(padded.back().y);
  }
  Packed p = pack(padded);
  Lightmap map;
  map.width = p.width, map.height = p.height, map.gutter = g, map.chartTexels = chartTexels;
  for (glm::ivec2 o : p.origins) map.origins.push_back(o + g);
  map.rgb.assign(std::size_t(map.width) * map.height, glm::vec3(0.0f));
  for (const Chart& c : atlas.charts) fillChart(atlas, B, c, g, options.dilate, map);
  return map;
}

}  // namespace hemirad
