#include "tests/shading/accuracy.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>
#include <vector>

#include "tests/shading/random_directions.h"

namespace hp::test {
std::string AccuracyStats::str() const {
  std::ostringstream os;
  os.precision(3);
  os << "median(e) = " << 100 * median << "%, p99(e) = " << 100 * p99 << "%, max(e) = " << 100 * max
     << "%, sum|dS|/sum|S| = " << 100 * relativeSum << "%";
  return os.str();
}

AccuracyStats measureAccuracy(const SEvaluator& mode, const HairMaterial& m, int samples, unsigned seed,
                              FibreModel model) {
  std::mt19937_64 rng(seed);
  std::vector<double> e;
  e.reserve(std::size_t(samples) * 3);
  double sumDiff = 0, sumExact = 0;
  for (int i = 0; i < samples; ++i) {
    Triple t = uniformTriple(rng);
    glm::dvec3 exact = exactS(model, t.L, t.V, t.T, m);
    glm::dvec3 approx = mode(t.L, t.V, t.T);
    for (int c = 0; c < 3; ++c) {
      double d = std::abs(approx[c] - exact[c]);
      e.push_back(d / (std::abs(exact[c]) + 0.01));
      sumDiff += d;
      sumExact += std::abs(exact[c]);
    }
  }
  AccuracyStats s;
  auto quantile = [&](double q) {
    auto it = e.begin() + std::ptrdiff_t(q * double(e.size() - 1));
    std::nth_element(e.begin(), it, e.end());
    return *it;
  };
  s.median = quantile(0.5);
  s.p99 = quantile(0.99);
  s.max = *std::max_element(e.begin(), e.end());
  s.relativeSum = sumDiff / sumExact;
  return s;
}
}  // namespace hp::test
