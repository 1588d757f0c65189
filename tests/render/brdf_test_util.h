#pragma once
// Contract: shared by the device BRDF tests: deterministic uniform (L, V, T) queries and the accuracy
// metric of docs/SHADING.md "Accuracy" (per sample and channel e = |S_mode - S_exact| / (|S_exact| + 0.01); median,
// p99, max of e and sum|dS| / sum|S|), here over device results.
#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "samples/tools/brdf_evaluator.h"
#include "tests/shading/random_directions.h"

namespace hp::test {
inline std::vector<render::BrdfQuery> randomQueries(std::size_t count, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::vector<render::BrdfQuery> q(count);
  for (auto& row : q) {
    Triple t = uniformTriple(rng);
    row = {glm::vec3(t.L), glm::vec3(t.V), glm::vec3(t.T)};
  }
  return q;
}

struct DeviceAccuracy {
  double median = 0, p99 = 0, max = 0, relativeSum = 0;
  std::size_t worst = 0;  // sample index of max(e)
  std::string str() const {
    std::ostringstream os;
    os.precision(3);
    os << "median(e) = " << 100 * median << "%, p99(e) = " << 100 * p99 << "%, max(e) = " << 100 * max
       << "%, sum|dS|/sum|S| = " << 100 * relativeSum << "%";
    return os.str();
  }
};

inline DeviceAccuracy compareWithExact(const std::vector<glm::vec3>& device, const std::vector<glm::dvec3>& exact) {
  std::vector<double> e;
  e.reserve(device.size() * 3);
  double sumDiff = 0, sumExact = 0;
  DeviceAccuracy a;
  for (std::size_t i = 0; i < device.size(); ++i)
    for (int c = 0; c < 3; ++c) {
      double d = std::abs(double(device[i][c]) - exact[i][c]);
      double ei = std::isfinite(d) ? d / (std::abs(exact[i][c]) + 0.01) : INFINITY;
      if (ei > a.max) {
        a.max = ei;
        a.worst = i;
      }
      e.push_back(ei);
      sumDiff += d;
      sumExact += std::abs(exact[i][c]);
    }
  auto quantile = [&](double q) {
    auto it = e.begin() + std::ptrdiff_t(q * double(e.size() - 1));
    std::nth_element(e.begin(), it, e.end());
    return *it;
  };
  a.median = quantile(0.5);
  a.p99 = quantile(0.99);
  a.relativeSum = sumDiff / sumExact;
  return a;
}
}  // namespace hp::test
