#include "engine/shading/lut_param.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace hp::shading {
double pseudoAngle(double a) {
  constexpr double r = 1.0 / std::numbers::sqrt2;
  return a <= std::numbers::pi / 4 ? std::sin(a) * r : 1.0 - std::cos(a) * r;
}

double pseudoAngleInverse(double x) {
  x = std::clamp(x, 0.0, 1.0);
  constexpr double s2 = std::numbers::sqrt2;
  return x <= 0.5 ? std::asin(std::min(1.0, x * s2)) : std::acos(std::min(1.0, (1.0 - x) * s2));
}
}  // namespace hp::shading
