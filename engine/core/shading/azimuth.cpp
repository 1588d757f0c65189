#include "engine/core/shading/azimuth.h"
#include "engine/core/shading/math_constants.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace hp::shading {
namespace {
struct CubicCoeffs {
  double a;  // linear coefficient
  double b;  // cubic coefficient (Phi = a g - b g^3 + p pi)
};

CubicCoeffs coeffs(int p, double etaPrime) {
  double c = std::asin(1.0 / etaPrime);
  return {6.0 * p * c / kPi - 2.0, 8.0 * p * c / (kPi * kPi * kPi)};
}

// Range of Phi over [-pi/2, pi/2]: endpoints plus interior stationary points.
void phiRange(int p, double etaPrime, double& lo, double& hi) {
  CubicCoeffs k = coeffs(p, etaPrime);
  double ends[4] = {phiCubic(p, -kPi / 2, etaPrime), phiCubic(p, kPi / 2, etaPrime), 0, 0};
  int n = 2;
  if (k.b > 0.0 && k.a > 0.0) {
    double g = std::sqrt(k.a / (3.0 * k.b));
    if (g < kPi / 2) {
      ends[n++] = phiCubic(p, g, etaPrime);
      ends[n++] = phiCubic(p, -g, etaPrime);
    }
  }
  lo = *std::min_element(ends, ends + n);
  hi = *std::max_element(ends, ends + n);
}

double polish(int p, double etaPrime, double target, double g) {
  for (int it = 0; it < 3; ++it) {
    double d = dPhiCubicDGamma(p, g, etaPrime);
    if (std::abs(d) < 1e-9) break;  // at a caustic the double root is already as good as it gets
    g -= (phiCubic(p, g, etaPrime) - target) / d;
  }
  return g;
}

void addRootsFor(int p, double etaPrime, double target, AzimuthRoots& out) {
  CubicCoeffs k = coeffs(p, etaPrime);
  std::array<double, 3> r{};
  int n = 0;
  double rhs = target - p * kPi;  // a g - b g^3 = rhs
  if (k.b == 0.0) {
    r[0] = rhs / k.a;
    n = 1;
  } else {
    n = solveDepressedCubic(-k.a / k.b, rhs / k.b, r);
  }
  for (int i = 0; i < n && out.count < out.gamma.size(); ++i) {
    double g = polish(p, etaPrime, target, r[i]);
    if (g >= -kPi / 2 && g <= kPi / 2) out.gamma[out.count++] = g;
  }
}
}  // namespace

double phiCubic(int p, double gamma, double etaPrime) {
  CubicCoeffs k = coeffs(p, etaPrime);
  return k.a * gamma - k.b * gamma * gamma * gamma + p * kPi;
}

double dPhiCubicDGamma(int p, double gamma, double etaPrime) {
  CubicCoeffs k = coeffs(p, etaPrime);
  return k.a - 3.0 * k.b * gamma * gamma;
}

int solveDepressedCubic(double P, double Q, std::array<double, 3>& out) {
  double disc = 0.25 * Q * Q + P * P * P / 27.0;
  if (disc > 0.0) {
    double s = std::sqrt(disc);
    out[0] = std::cbrt(-0.5 * Q + s) + std::cbrt(-0.5 * Q - s);
    return 1;
  }
  // Three real roots (P < 0, or the triple root P = Q = 0): trigonometric form.
  if (P == 0.0) {
    out[0] = out[1] = out[2] = 0.0;
    return 3;
  }
  double m = 2.0 * std::sqrt(-P / 3.0);
  double arg = std::clamp(3.0 * Q / (P * m), -1.0, 1.0);
  double theta = std::acos(arg) / 3.0;
  for (int j = 0; j < 3; ++j) out[j] = m * std::cos(theta - 2.0 * kPi * j / 3.0);
  std::sort(out.begin(), out.end());
  return 3;
}

AzimuthRoots azimuthRoots(int p, double etaPrime, double phi) {
  AzimuthRoots roots;
  double lo = 0, hi = 0;
  phiRange(p, etaPrime, lo, hi);
  int kMin = static_cast<int>(std::ceil((lo - phi) / (2.0 * kPi) - 1e-12));
  int kMax = static_cast<int>(std::floor((hi - phi) / (2.0 * kPi) + 1e-12));
  for (int k = kMin; k <= kMax; ++k) addRootsFor(p, etaPrime, phi + 2.0 * kPi * k, roots);
  return roots;
}

double phiExactTRT(double h, double etaPrime) {
  return 4.0 * std::asin(h / etaPrime) - 2.0 * std::asin(h) + 2.0 * kPi;
}

double d2PhiExactTRTdH2(double h, double etaPrime) {
  double a = etaPrime * etaPrime - h * h;
  double b = 1.0 - h * h;
  return 4.0 * h / (a * std::sqrt(a)) - 2.0 * h / (b * std::sqrt(b));
}
}  // namespace hp::shading
