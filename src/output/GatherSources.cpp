#include "src/output/GatherSources.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "src/scene/Scene.h"
#include "src/solver/Subdivide.h"

namespace hemirad {

namespace {

// Neighbours' centroids nearer than this many cells along an axis give no change (a sliver), and
// a piece is at least this share of its cell along it.
constexpr double kMinCentroidStep = 0.05;

// Per node, the first two vec4s: the area-weighted mean of `sent`, and the sums of w x and of w.
void nodeLight(const Atlas& atlas, const std::vector<ShooterNode>& nodes, const std::vector<glm::vec4>& sent,
               std::vector<glm::vec4>& out) {
  for (std::size_t n = 0; n < nodes.size(); ++n) {
    const glm::ivec4 r = nodes[n].rect;
    glm::dvec3 sum(0.0), centre(0.0);
    double area = 0, weight = 0;
    for (int y = r.y; y < r.y + r.w; ++y)
      for (int x = r.x; x < r.x + r.z; ++x) {
        const std::size_t t = std::size_t(y) * atlas.width + x;
        if (atlas.polygonOf[t] == kNoPolygon || atlas.positionArea[t].w <= 0) continue;
        const double a = atlas.positionArea[t].w, l = luminance(glm::dvec3(glm::vec3(sent[t])));
        sum += glm::dvec3(glm::vec3(sent[t])) * a;
        area += a, weight += l * a;
        centre += glm::dvec3(atlas.positionArea[t]) * (l * a);
      }
    if (area <= 0) continue;
    out[n * 4] = glm::vec4(glm::vec3(sum / area), 0.0f);
    out[n * 4 + 1] = glm::vec4(glm::vec3(centre), float(weight));
  }
}

// Along one axis of element t (a unit chart axis, cell side h; `offset` its centroid's from its
// cell's centre along the axis, in cells): its piece's extent in cells and the change of its
// luminance per cell. The grid is centred on its chart, so the outer cells are cut by the
// polygon's edge: a border piece's centroid lies off its cell's centre, nearer the next one. So the
// changes are over the true distances between centroids (one cell only inside), then the
// parabola's slope through the neighbours, limited (centralLimitedSlope), or at the chart's edge
// through the next two (edgeSlope).
struct AxisChange {
  double extent = 1, perCell = 0;
};

AxisChange axisChange(const Atlas& atlas, const std::vector<glm::vec4>& sent, glm::ivec2 t, glm::ivec2 step,
                      const glm::dvec3& axis, double h, double offset) {
  const std::size_t i = std::size_t(t.y) * std::size_t(atlas.width) + std::size_t(t.x);
  const std::uint32_t chart = atlas.chartAt(i);
  const glm::dvec3 p(atlas.positionArea[i]);
  struct Sample {
    double light, cells;  // luminance, and distance from t along the axis
  };
  auto sample = [&](glm::ivec2 q) -> std::optional<Sample> {
    if (q.x < 0 || q.y < 0 || q.x >= atlas.width || q.y >= atlas.height) return std::nullopt;
    const std::size_t k = std::size_t(q.y) * std::size_t(atlas.width) + std::size_t(q.x);
    if (atlas.chartAt(k) != chart || !(atlas.positionArea[k].w > 0)) return std::nullopt;
    const double d = std::abs(glm::dot(glm::dvec3(atlas.positionArea[k]) - p, axis)) / h;
    if (d < kMinCentroidStep) return std::nullopt;
    return Sample{luminance(glm::dvec3(glm::vec3(sent[k]))), d};
  };
  const double own = luminance(glm::dvec3(glm::vec3(sent[i])));
  const std::optional<Sample> up = sample(t + step), down = sample(t - step);
  AxisChange a{std::clamp(1 - 2 * std::abs(offset), kMinCentroidStep, 1.0), 0.0};
  if (up && down)
    a.perCell =
        centralLimitedSlope((up->light - own) / up->cells, (own - down->light) / down->cells, up->cells, down->cells);
  else if (up || down) {
    const int sign = up ? 1 : -1;  // toward the chart's inside
    const Sample next = up ? *up : *down;
    const std::optional<Sample> after = sample(t + 2 * sign * step);
    a.perCell = sign * (next.light - own) / next.cells;
    if (after && after->cells > next.cells + kMinCentroidStep) {
      const double farStep = after->cells - next.cells;
      a.perCell = edgeSlope(a.perCell, sign * (after->light - next.light) / farStep, next.cells, farStep);
    }
  }
  return a;
}

// The last two vec4s of a single element of a planar projection chart (others keep 0: constant).
void elementProfile(const Atlas& atlas, const ShooterNode& node, const std::vector<glm::vec4>& sent, glm::vec4* out) {
  const glm::ivec4 r = node.rect;
  if (r.z != 1 || r.w != 1 || node.polygon == kNoPolygon) return;
  const std::size_t t = std::size_t(r.y) * atlas.width + r.x;
  const Chart& chart = atlas.charts[atlas.chartOf[node.polygon]];
  const double own = luminance(glm::dvec3(glm::vec3(sent[t])));
  if (chart.uvMapped() || !chart.planar || atlas.positionArea[t].w <= 0 || own <= 0) return;
  const double h = chart.cellSize;
  const glm::dvec2 cell = glm::dvec2(r.x - chart.origin.x, r.y - chart.origin.y) + 0.5;
  const glm::dvec2 offset = (chart.frame.project(glm::dvec3(atlas.positionArea[t])) - chart.corner) / h - cell;
  const AxisChange u = axisChange(atlas, sent, {r.x, r.y}, {1, 0}, chart.frame.u, h, offset.x),
                   v = axisChange(atlas, sent, {r.x, r.y}, {0, 1}, chart.frame.v, h, offset.y);
  // Across the piece, relative to its own light; within +-4 its sub-cells stay >= 0.
  glm::dvec2 change = glm::clamp(glm::dvec2(u.perCell * u.extent, v.perCell * v.extent) / own, -4.0, 4.0);
  glm::dvec3 hu = chart.frame.u * (u.extent * h / 2), hv = chart.frame.v * (v.extent * h / 2);
  if (glm::dot(glm::cross(hu, hv), glm::dvec3(node.normal)) < 0) std::swap(hu, hv), std::swap(change.x, change.y);
  out[2] = glm::vec4(glm::vec3(hu), float(change.x));
  out[3] = glm::vec4(glm::vec3(hv), float(change.y));
}

}  // namespace

std::vector<glm::vec4> gatherSources(const Atlas& atlas, const std::vector<ShooterNode>& nodes,
                                     const std::vector<glm::vec4>& sent) {
  std::vector<glm::vec4> out(nodes.size() * 4, glm::vec4(0.0f));
  nodeLight(atlas, nodes, sent, out);
  for (std::size_t n = 0; n < nodes.size(); ++n) elementProfile(atlas, nodes[n], sent, &out[n * 4]);
  return out;
}

}  // namespace hemirad
