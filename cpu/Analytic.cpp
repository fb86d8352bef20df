#include "cpu/Analytic.h"

#include <cmath>

namespace hemirad::cpu {

double parallelRectangles(double a, double b, double c) {
  const double X = a / c, Y = b / c, x2 = 1 + X * X, y2 = 1 + Y * Y;
  return 2.0 / (M_PI * X * Y) *
         (std::log(std::sqrt(x2 * y2 / (x2 + Y * Y))) + X * std::sqrt(y2) * std::atan(X / std::sqrt(y2)) +
          Y * std::sqrt(x2) * std::atan(Y / std::sqrt(x2)) - X * std::atan(X) - Y * std::atan(Y));
}

double perpendicularRectangles(double l, double w, double h) {
  const double H = h / l, W = w / l, H2 = H * H, W2 = W * W, S = H2 + W2;
  const double a = (1 + W2) * (1 + H2) / (1 + S);
  const double b = W2 * (1 + S) / ((1 + W2) * S);
  const double c = H2 * (1 + S) / ((1 + H2) * S);
  return 1.0 / (M_PI * W) *
         (W * std::atan(1 / W) + H * std::atan(1 / H) - std::sqrt(S) * std::atan(1 / std::sqrt(S)) +
          0.25 * (std::log(a) + W2 * std::log(b) + H2 * std::log(c)));
}

double pointToCoaxialDisc(double R, double H) { return R * R / (R * R + H * H); }

}  // namespace hemirad::cpu
