#pragma once
// Contract: the exit azimuth Phi(p, gamma_i) of docs/THEORY.md §3.4 and the root finding that N_p needs.
// Cubic form: Phi(p, g) = (6pc/pi - 2) g - (8pc/pi^3) g^3 + p pi, c = asin(1/eta').
// azimuthRoots() returns every gamma in [-pi/2, pi/2] with Phi(p, gamma) = phi + 2 pi k for ANY
// integer k (p = 0, 1, 2 ...), each polished by Newton steps. The exact TRT form
// Phi(2, h) = 4 asin(h/eta') - 2 asin(h) + 2 pi and its h-derivatives serve the caustic.
#include <array>
#include <cstddef>

namespace hp::shading {
struct AzimuthRoots {
  std::array<double, 24> gamma{};
  std::size_t count = 0;
};

double phiCubic(int p, double gamma, double etaPrime);
double dPhiCubicDGamma(int p, double gamma, double etaPrime);
AzimuthRoots azimuthRoots(int p, double etaPrime, double phi);

double phiExactTRT(double h, double etaPrime);
double d2PhiExactTRTdH2(double h, double etaPrime);

// Real roots of x^3 + P x + Q = 0 (1 or 3, ascending), written to out; returns the count.
int solveDepressedCubic(double P, double Q, std::array<double, 3>& out);
}  // namespace hp::shading
