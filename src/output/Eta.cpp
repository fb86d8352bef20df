#include "src/output/Eta.h"

#include <cmath>

namespace hemirad {

void EtaModel::add(unsigned shots, double convergence) {
  if (shots == 0 || !std::isfinite(convergence)) return;
  if (!points_.empty() && double(shots) <= points_.back().first) return;
  points_.emplace_back(double(shots), 1.0 - convergence);
}

std::optional<double> EtaModel::shotsLeft(double target) const {
  if (points_.empty()) return std::nullopt;
  const auto [n, u] = points_.back();
  const double goal = 1.0 - target;
  if (u <= goal) return 0.0;
  // Least squares of ln u against n over the points in the last half of the shots so far.
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int count = 0;
  for (const auto& [shots, unshot] : points_) {
    if (shots < 0.5 * n || !(unshot > 0)) continue;
    const double x = shots, y = std::log(unshot);
    sx += x, sy += y, sxx += x * x, sxy += x * y, ++count;
  }
  if (count < 3) return std::nullopt;
  const double denom = count * sxx - sx * sx;
  if (!(denom > 0)) return std::nullopt;
  const double slope = (count * sxy - sx * sy) / denom;  // -k
  if (!(slope < 0)) return std::nullopt;
  // From the latest point along the fitted slope: ln goal = ln u + slope (n_end - n).
  const double left = std::log(goal / u) / slope;
  return std::isfinite(left) ? std::max(0.0, left) : std::optional<double>();
}

}  // namespace hemirad
