#include "src/scene/ContactCuts.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "src/scene/Leaves.h"

namespace hemirad {

namespace {

struct Piece {
  Poly2 shape;  // convex, counter-clockwise in the chart's frame
  int part;     // the chart part it was cut from
};

// Signed distance of p left of the line through a, b.
double sideOf(glm::dvec2 a, glm::dvec2 b, glm::dvec2 p) {
  const glm::dvec2 d = b - a;
  return (d.x * (p.y - a.y) - d.y * (p.x - a.x)) / glm::length(d);
}

// Convex p cut by the line through a, b; false (nothing cut) if either side is thinner than `tolerance`.
bool splitPiece(const Poly2& p, glm::dvec2 a, glm::dvec2 b, double tolerance, Poly2& left, Poly2& right) {
  std::vector<double> s;  // a vertex within rounding of the line is on it: no near-duplicate vertex beside it
  for (glm::dvec2 v : p) s.push_back(std::abs(sideOf(a, b, v)) <= 1e-3 * tolerance ? 0.0 : sideOf(a, b, v));
  if (*std::max_element(s.begin(), s.end()) <= tolerance || *std::min_element(s.begin(), s.end()) >= -tolerance)
    return false;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const std::size_t j = (i + 1) % p.size();
    if (s[i] >= 0) left.push_back(p[i]);
    if (s[i] <= 0) right.push_back(p[i]);
    if ((s[i] > 0 && s[j] < 0) || (s[i] < 0 && s[j] > 0)) {
      const glm::dvec2 x = p[i] + (p[j] - p[i]) * (s[i] / (s[i] - s[j]));
      left.push_back(x), right.push_back(x);
    }
  }
  return left.size() >= 3 && right.size() >= 3;
}

// The chart's parts cut along each line, across only the pieces the line crosses.
std::vector<Piece> cutPieces(const Chart& c, const std::vector<const ContactLine*>& lines, double tolerance) {
  std::vector<Piece> pieces;
  for (std::size_t k = 0; k < c.parts.size(); ++k) {
    Poly2 q;
    for (const glm::dvec3& v : c.parts[k]) q.push_back(c.frame.project(v));
    if (signedArea(q) < 0) std::reverse(q.begin(), q.end());
    pieces.push_back({std::move(q), int(k)});
  }
  std::vector<glm::dvec4> box;  // per piece: lo x, lo y, hi x, hi y
  auto boxOf = [](const Poly2& p) {
    glm::dvec2 lo(1e300), hi(-1e300);
    for (glm::dvec2 v : p) lo = glm::min(lo, v), hi = glm::max(hi, v);
    return glm::dvec4(lo, hi);
  };
  for (const Piece& p : pieces) box.push_back(boxOf(p.shape));
  for (const ContactLine* line : lines) {
    const glm::dvec2 lo = glm::min(line->a, line->b), hi = glm::max(line->a, line->b);
    for (std::size_t i = 0, n = pieces.size(); i < n; ++i) {
      if (hi.x < box[i].x || box[i].z < lo.x || hi.y < box[i].y || box[i].w < lo.y) continue;
      double t0, t1;
      if (!clipSegment(pieces[i].shape, line->a, line->b, tolerance, t0, t1) ||
          (t1 - t0) * glm::length(line->b - line->a) <= tolerance)
        continue;
      Poly2 left, right;
      if (!splitPiece(pieces[i].shape, line->a, line->b, tolerance, left, right)) continue;
      box[i] = boxOf(left), box.push_back(boxOf(right));
      pieces[i].shape = std::move(left);
      pieces.push_back({std::move(right), pieces[i].part});
    }
  }
  return pieces;
}

// Length of [lo, hi] that no interval of `cover` covers.
double uncovered(double lo, double hi, std::vector<glm::dvec2> cover) {
  std::sort(cover.begin(), cover.end(), [](glm::dvec2 x, glm::dvec2 y) { return x.x < y.x; });
  double free = 0, at = lo;
  for (glm::dvec2 c : cover) {
    if (c.x > at) free += std::min(c.x, hi) - at;
    at = std::max(at, c.y);
    if (at >= hi) return free;
  }
  return free + std::max(0.0, hi - at);
}

// Whether pieces p and q share a stretch of boundary that no contact line runs along.
bool joined(const Poly2& p, const Poly2& q, const std::vector<const ContactLine*>& lines, double tolerance) {
  for (std::size_t i = 0; i < p.size(); ++i) {
    const glm::dvec2 p0 = p[i], d = p[(i + 1) % p.size()] - p0;
    const double len = glm::length(d);
    if (len <= tolerance) continue;
    const glm::dvec2 u = d / len, n(-u.y, u.x);
    auto on = [&](glm::dvec2 x) { return std::abs(glm::dot(x - p0, n)) <= tolerance; };
    for (std::size_t j = 0; j < q.size(); ++j) {
      const glm::dvec2 q0 = q[j], q1 = q[(j + 1) % q.size()];
      if (!on(q0) || !on(q1)) continue;
      const double a = glm::dot(q0 - p0, u), b = glm::dot(q1 - p0, u);
      const double lo = std::max(0.0, std::min(a, b)), hi = std::min(len, std::max(a, b));
      if (hi - lo <= tolerance) continue;
      std::vector<glm::dvec2> cover;
      for (const ContactLine* l : lines)
        if (on(l->a) && on(l->b)) {
          const double la = glm::dot(l->a - p0, u), lb = glm::dot(l->b - p0, u);
          cover.push_back({std::min(la, lb), std::max(la, lb)});
        }
      if (uncovered(lo, hi, std::move(cover)) > tolerance) return true;
    }
  }
  return false;
}

int pieceRoot(std::vector<int>& parent, int i) {
  while (parent[std::size_t(i)] != i) i = parent[std::size_t(i)] = parent[std::size_t(parent[std::size_t(i)])];
  return i;
}

// +1 (left) or -1 (right) if piece p has a stretch of boundary along line l, else 0.
int sideAlong(const Poly2& p, const ContactLine& l, double tolerance) {
  const double len = glm::length(l.b - l.a);
  const glm::dvec2 u = (l.b - l.a) / len, n(-u.y, u.x);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const glm::dvec2 p0 = p[i] - l.a, p1 = p[(i + 1) % p.size()] - l.a;
    if (std::abs(glm::dot(p0, n)) > tolerance || std::abs(glm::dot(p1, n)) > tolerance) continue;
    const double a = glm::dot(p0, u), b = glm::dot(p1, u);
    if (std::min(len, std::max(a, b)) - std::max(0.0, std::min(a, b)) > tolerance)
      return glm::dot(centroid(p) - l.a, n) > 0 ? 1 : -1;
  }
  return 0;
}

// Per piece, its component: pieces joined off the contact lines. Should a line's two sides still
// end up in one component (a line with free ends: a blade standing on the floor, a footprint
// only partly within the contact distance), the pieces along that line are charts of their own,
// so no chart holds both sides of it.
std::vector<int> components(const std::vector<Piece>& pieces, const std::vector<const ContactLine*>& lines,
                            double tolerance) {
  std::vector<glm::dvec4> box;  // lo x, lo y, hi x, hi y, grown by the tolerance
  for (const Piece& p : pieces) {
    glm::dvec2 lo(1e300), hi(-1e300);
    for (glm::dvec2 v : p.shape) lo = glm::min(lo, v), hi = glm::max(hi, v);
    box.push_back({lo - tolerance, hi + tolerance});
  }
  auto meet = [&](std::size_t i, std::size_t j) {
    return box[i].x <= box[j].z && box[j].x <= box[i].z && box[i].y <= box[j].w && box[j].y <= box[i].w;
  };
  std::vector<int> parent(pieces.size());
  std::vector<char> alone(pieces.size(), 0);
  auto join = [&] {
    std::iota(parent.begin(), parent.end(), 0);
    for (std::size_t i = 0; i < pieces.size(); ++i)
      for (std::size_t j = i + 1; j < pieces.size() && !alone[i]; ++j)
        if (!alone[j] && meet(i, j) && joined(pieces[i].shape, pieces[j].shape, lines, tolerance))
          parent[std::size_t(pieceRoot(parent, int(i)))] = pieceRoot(parent, int(j));
  };
  join();
  bool rejoin = false;
  for (const ContactLine* l : lines) {
    std::vector<int> along, left, right;
    const glm::dvec2 lo = glm::min(l->a, l->b) - tolerance, hi = glm::max(l->a, l->b) + tolerance;
    for (std::size_t i = 0; i < pieces.size(); ++i) {
      if (hi.x < box[i].x || box[i].z < lo.x || hi.y < box[i].y || box[i].w < lo.y) continue;
      if (const int side = sideAlong(pieces[i].shape, *l, tolerance); side != 0)
        along.push_back(int(i)), (side > 0 ? left : right).push_back(pieceRoot(parent, int(i)));
    }
    const bool shared = std::any_of(left.begin(), left.end(),
                                    [&](int r) { return std::find(right.begin(), right.end(), r) != right.end(); });
    if (shared)
      for (int i : along) alone[std::size_t(i)] = 1, rejoin = true;
  }
  if (rejoin) join();
  std::vector<int> out(pieces.size());
  for (std::size_t i = 0; i < pieces.size(); ++i) out[i] = pieceRoot(parent, int(i));
  return out;
}

// The lines of chart c that belong to a chain (lines meeting end to end) at least kMinContactCells
// cells across: a contact smaller than a cell (a chair leg's round foot under coarse texels) is
// left to its texel, not cut into pieces of a few percent of a cell each.
std::vector<const ContactLine*> largeContacts(const std::vector<const ContactLine*>& lines, double cell,
                                              double tolerance) {
  std::vector<int> parent(lines.size());
  std::iota(parent.begin(), parent.end(), 0);
  std::vector<std::pair<glm::dvec2, int>> ends;  // every endpoint and its line, by x
  for (std::size_t i = 0; i < lines.size(); ++i)
    ends.push_back({lines[i]->a, int(i)}), ends.push_back({lines[i]->b, int(i)});
  std::sort(ends.begin(), ends.end(), [](const auto& x, const auto& y) { return x.first.x < y.first.x; });
  for (std::size_t i = 0; i < ends.size(); ++i)
    for (std::size_t j = i + 1; j < ends.size() && ends[j].first.x - ends[i].first.x <= tolerance; ++j)
      if (glm::length(ends[j].first - ends[i].first) <= tolerance)
        parent[std::size_t(pieceRoot(parent, ends[i].second))] = pieceRoot(parent, ends[j].second);
  std::vector<glm::dvec4> extent(lines.size(), glm::dvec4(1e300, 1e300, -1e300, -1e300));
  for (std::size_t i = 0; i < lines.size(); ++i) {
    glm::dvec4& e = extent[std::size_t(pieceRoot(parent, int(i)))];
    const glm::dvec2 lo = glm::min(glm::min(lines[i]->a, lines[i]->b), glm::dvec2(e.x, e.y));
    const glm::dvec2 hi = glm::max(glm::max(lines[i]->a, lines[i]->b), glm::dvec2(e.z, e.w));
    e = glm::dvec4(lo, hi);
  }
  std::vector<const ContactLine*> out;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const glm::dvec4& e = extent[std::size_t(pieceRoot(parent, int(i)))];
    if (std::max(e.z - e.x, e.w - e.y) >= kMinContactCells * cell) out.push_back(lines[i]);
  }
  return out;
}

// One chart of the pieces in component `root`, on the receiver's grid lattice.
void addComponent(const Scene& scene, const Chart& c, const std::vector<Piece>& pieces, const std::vector<int>& comp,
                  int root, ContactLayout& out) {
  ChartSpec spec;
  spec.frame = c.frame, spec.cellSize = c.cellSize;
  spec.group.axis = c.frame.n, spec.group.planar = true;
  glm::dvec2 lo(1e300), hi(-1e300);
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    if (comp[i] != root) continue;
    const ScenePolygon& on = scene.polygons()[std::size_t(c.partPolygon[std::size_t(pieces[i].part)])];
    Poly3 lifted;
    for (glm::dvec2 v : pieces[i].shape) lifted.push_back(c.frame.lift(v)), lo = glm::min(lo, v), hi = glm::max(hi, v);
    if (!out.scene.addPolygon(lifted, on.material, on.object)) continue;
    const int id = int(out.scene.polygons().size()) - 1;
    spec.group.polygons.push_back(id), spec.group.parts.push_back(lifted), spec.group.partPolygon.push_back(id);
  }
  if (spec.group.parts.empty()) return;
  const glm::dvec2 first = glm::floor((lo - c.corner) / c.cellSize + 1e-9);
  const glm::dvec2 last = glm::ceil((hi - c.corner) / c.cellSize - 1e-9);
  spec.corner = c.corner + first * c.cellSize;
  spec.size = glm::max(glm::ivec2(1), glm::ivec2(last - first));
  out.specs.push_back(std::move(spec));
}

}  // namespace

std::optional<ContactLayout> cutAlongContacts(const Scene& scene, const Atlas& atlas,
                                              const std::vector<ContactLine>& lines) {
  if (lines.empty()) return std::nullopt;
  ContactLayout out{sceneLike(scene), {}, 0, 0, 0};
  const double tolerance = kContactTolerance * glm::length(scene.boundsMax() - scene.boundsMin());
  std::vector<std::vector<const ContactLine*>> byChart(atlas.charts.size());
  for (const ContactLine& l : lines) byChart[std::size_t(l.chart)].push_back(&l);
  for (std::size_t c = 0; c < atlas.charts.size(); ++c) {
    const Chart& chart = atlas.charts[c];
    byChart[c] = largeContacts(byChart[c], chart.cellSize, tolerance);
    std::vector<Piece> pieces;
    if (!byChart[c].empty()) pieces = cutPieces(chart, byChart[c], tolerance);
    if (pieces.size() <= chart.parts.size()) {  // nothing cut
      out.specs.push_back(copyChart(scene, chart, out.scene));
      continue;
    }
    const std::vector<int> comp = components(pieces, byChart[c], tolerance);
    for (std::size_t i = 0; i < pieces.size(); ++i)
      if (comp[i] == int(i)) addComponent(scene, chart, pieces, comp, int(i), out);
    for (const ContactLine* l : byChart[c])
      out.scene.creases.push_back({chart.frame.lift(l->a), chart.frame.lift(l->b)});
    out.lines += byChart[c].size(), ++out.charts, out.pieces += pieces.size();
  }
  if (out.charts == 0) return std::nullopt;
  return out;
}

}  // namespace hemirad
