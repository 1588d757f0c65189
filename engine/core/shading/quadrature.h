#pragma once
// Contract: composite 8-point Gauss-Legendre quadrature on [a, b] split into `panels` equal panels:
// calls f(x, weight) for every node, so int_a^b g(x) dx ~ sum of weight * g(x). Exact for polynomials
// of degree 15 per panel. Used by the physical fibre model's integrals over h and the white furnace.
#include <array>

namespace hp::shading {
template <class F>
void gaussLegendre(double a, double b, int panels, F&& f) {
  static constexpr std::array<double, 4> kNode = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                                                  0.9602898564975363};
  static constexpr std::array<double, 4> kWeight = {0.3626837833783620, 0.3137066458778873,
                                                    0.2223810344533745, 0.1012285362903763};
  double width = (b - a) / panels;
  for (int i = 0; i < panels; ++i) {
    double mid = a + (i + 0.5) * width, half = 0.5 * width;
    for (int k = 0; k < 4; ++k) {
      f(mid - half * kNode[k], half * kWeight[k]);
      f(mid + half * kNode[k], half * kWeight[k]);
    }
  }
}
}  // namespace hp::shading
