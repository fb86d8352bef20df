#include "src/scene/AtlasPacker.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <iterator>
#include <map>
#include <set>
#include <tuple>

namespace hemirad {

namespace {

// The skyline: segments by x (adjacent ones at one height merged), and by (y, x) for the lowest.
class Skyline {
 public:
  explicit Skyline(int width) { add(0, 0, width); }
  // The lowest segment, leftmost: x, y, width.
  glm::ivec3 lowest() const {
    const auto [y, x] = *byHeight_.begin();
    return {x, y, byX_.at(x).w};
  }
  // Neighbours' heights of the segment at x (INT_MAX: the strip's edge).
  int leftY(int x) const {
    auto it = byX_.find(x);
    return it == byX_.begin() ? INT_MAX : std::prev(it)->second.y;
  }
  int rightY(int x) const {
    auto it = std::next(byX_.find(x));
    return it == byX_.end() ? INT_MAX : it->second.y;
  }
  // Raises the segment at x by h over [x + offset, x + offset + w), merging equal neighbours.
  void place(int x, int offset, int w, int h) {
    const Segment s = byX_.at(x);
    remove(x);
    if (offset > 0) add(x, s.y, offset);
    add(x + offset, s.y + h, w);
    if (offset + w < s.w) add(x + offset + w, s.y, s.w - offset - w);
    mergeAround(x + offset);
  }
  // Raises the segment at x to its lower neighbour's height (a gap no rectangle fits).
  void raise(int x) {
    const int y = std::min(leftY(x), rightY(x)), w = byX_.at(x).w;
    remove(x);
    add(x, y, w);
    mergeAround(x);
  }
  int top() const {
    int t = 0;
    for (auto& [x, s] : byX_) t = std::max(t, s.y);
    return t;
  }

 private:
  struct Segment {
    int y, w;
  };
  void add(int x, int y, int w) { byX_[x] = {y, w}, byHeight_.insert({y, x}); }
  void remove(int x) { byHeight_.erase({byX_.at(x).y, x}), byX_.erase(x); }
  // Joins the segment at x with its neighbours at its height.
  void mergeAround(int x) {
    auto it = byX_.find(x);
    if (it != byX_.begin() && std::prev(it)->second.y == it->second.y) {
      const int w = it->second.w;
      remove(x);
      it = std::prev(byX_.lower_bound(x));
      x = it->first;
      const int y = it->second.y, total = it->second.w + w;
      remove(x), add(x, y, total);
      it = byX_.find(x);
    }
    auto next = std::next(it);
    if (next != byX_.end() && next->second.y == it->second.y) {
      const int y = it->second.y, total = it->second.w + next->second.w;
      remove(next->first), remove(x), add(x, y, total);
    }
  }
  std::map<int, Segment> byX_;
  std::set<std::pair<int, int>> byHeight_;
};

// A rectangle as it would lie in a gap: (width in the gap, height, -index, turned); the set's
// last entry of width <= the gap is the best fit (widest, then tallest, then lowest index).
using Fit = std::tuple<int, int, int, int>;

void addFits(std::set<Fit>& fits, glm::ivec2 s, int id) {
  fits.insert({s.x, s.y, -id, 0});
  if (s.x != s.y) fits.insert({s.y, s.x, -id, 1});
}
void removeFits(std::set<Fit>& fits, glm::ivec2 s, int id) {
  fits.erase({s.x, s.y, -id, 0}), fits.erase({s.y, s.x, -id, 1});
}
}  // namespace

RectLayout packBestFit(const std::vector<glm::ivec2>& sizes, int width) {
  RectLayout l;
  l.width = width;
  l.origins.assign(sizes.size(), glm::ivec2(0));
  l.turned.assign(sizes.size(), 0);
  std::set<Fit> fits;
  for (std::size_t i = 0; i < sizes.size(); ++i) addFits(fits, sizes[i], int(i));
  Skyline sky(width);
  while (!fits.empty()) {
    ++l.steps;
    const glm::ivec3 gap = sky.lowest();
    auto it = fits.upper_bound({gap.z, INT_MAX, INT_MAX, INT_MAX});
    if (it == fits.begin()) {
      sky.raise(gap.x);
      continue;
    }
    const auto [w, h, negId, turned] = *std::prev(it);
    const int id = -negId;
    removeFits(fits, sizes[std::size_t(id)], id);
    // Against the taller neighbour: the lower side stays open for the next fit.
    const int offset = sky.leftY(gap.x) >= sky.rightY(gap.x) ? 0 : gap.z - w;
    l.origins[std::size_t(id)] = glm::ivec2(gap.x + offset, gap.y);
    l.turned[std::size_t(id)] = char(turned);
    sky.place(gap.x, offset, w, h);
  }
  l.height = sky.top();
  return l;
}

namespace {
// Ranks layouts: within the texture limit, then sides within kSquarish : 1 (a long atlas pads
// to a large power-of-two square in the stochastic pyramid, shaders/pyramid.comp), then fewest
// texels; ties keep the earlier.
constexpr double kSquarish = 2;
struct Rank {
  bool fits = false, squarish = false;
  double texels = 1e300;
  bool operator<(const Rank& o) const {
    if (fits != o.fits) return fits;
    if (squarish != o.squarish) return squarish;
    return texels < o.texels;
  }
};
Rank rank(const RectLayout& l, int maxSize) {
  const double w = l.width, h = l.height;
  return {l.width <= maxSize && l.height <= maxSize, std::max(w, h) <= kSquarish * std::min(w, h), w * h};
}
}  // namespace

RectLayout packAtlasCharts(const std::vector<glm::ivec2>& sizes, int maxSize) {
  double area = 0;
  int narrowest = 1, longest = 1;  // every rectangle fits a strip `narrowest` wide, one way or the other
  for (glm::ivec2 s : sizes)
    area += double(s.x) * s.y, narrowest = std::max(narrowest, std::min(s.x, s.y)),
                               longest = std::max({longest, s.x, s.y});
  const int square = std::max(narrowest, int(std::ceil(std::sqrt(area))));
  RectLayout best;
  Rank bestRank;
  // Near the square; and as wide as the longest side, for a few long charts (one 1000 x 3 chart
  // stands in a strip 55 wide, 5 % full, but lies in one 1000 wide).
  for (double stretch : {1.0, 1.03, 1.07, 1.15, 1.3, 0.0}) {
    const int width = stretch > 0 ? std::max(narrowest, int(std::ceil(square * stretch))) : longest;
    if (width > maxSize && bestRank.fits) continue;
    RectLayout l = packBestFit(sizes, width);
    if (const Rank r = rank(l, maxSize); r < bestRank) best = std::move(l), bestRank = r;
  }
  return best;
}

}  // namespace hemirad
