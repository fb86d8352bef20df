#include "src/output/Eta.h"

#include <cmath>

namespace hemirad {

void EtaModel::add(unsigned shots, double convergence) {
  if (shots == 0 || !std::isfinite(convergence)) return;
  if (!points_.empty() && double(shots) <= points_.back().first) return;
  points_.emplace_back(double(shots), 1.0 - convergence);
}

namespace {

// u = a e^(-k n^(1 - kStretch)), fitted over the shots after kWarmUp of those so far (Eta.h).
constexpr double kStretch = 0.15, kWarmUp = 0.3;

double stretched(double shots) { return std::pow(shots, 1.0 - kStretch); }

}  // namespace

std::optional<double> EtaModel::shotsLeft(double target) const {
  if (points_.empty()) return std::nullopt;
  const auto [n, u] = points_.back();
  const double goal = 1.0 - target;
  if (u <= goal) return 0.0;
  // Least squares of ln u against n^(1 - kStretch) over the points past the warm-up.
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int count = 0;
  for (const auto& [shots, unshot] : points_) {
    if (shots < kWarmUp * n || !(unshot > 0)) continue;
    const double x = stretched(shots), y = std::log(unshot);
    sx += x, sy += y, sxx += x * x, sxy += x * y, ++count;
  }
  if (count < 3) return std::nullopt;
  const double denom = count * sxx - sx * sx;
  if (!(denom > 0)) return std::nullopt;
  const double slope = (count * sxy - sx * sy) / denom;  // -k
  if (!(slope < 0)) return std::nullopt;
  // From the latest point along the fitted curve: ln goal = ln u + slope (x(n_end) - x(n)).
  const double end = std::pow(stretched(n) + std::log(goal / u) / slope, 1.0 / (1.0 - kStretch));
  return std::isfinite(end) ? std::max(0.0, end - n) : std::optional<double>();
}

}  // namespace hemirad
