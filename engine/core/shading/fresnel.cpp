#include "engine/core/shading/fresnel.h"

#include <cmath>

namespace hp::shading {
namespace {
// cos of the refracted angle for relative index n, or a negative value under TIR.
double cosRefracted(double n, double cosI) {
  double sinI2 = 1.0 - cosI * cosI;
  double sinT2 = sinI2 / (n * n);
  return sinT2 >= 1.0 ? -1.0 : std::sqrt(1.0 - sinT2);
}
}  // namespace

double fresnelS(double n, double gamma) {
  double ci = std::abs(std::cos(gamma));
  double ct = cosRefracted(n, ci);
  if (ct < 0.0) return 1.0;
  double r = (ci - n * ct) / (ci + n * ct);
  return r * r;
}

double fresnelP(double n, double gamma) {
  double ci = std::abs(std::cos(gamma));
  double ct = cosRefracted(n, ci);
  if (ct < 0.0) return 1.0;
  double r = (n * ci - ct) / (n * ci + ct);
  return r * r;
}

double fresnel(double n1, double n2, double gamma) {
  return 0.5 * (fresnelS(n1, gamma) + fresnelP(n2, gamma));
}
}  // namespace hp::shading
