#pragma once
// Contract: deterministic uniform unit vectors (and (L, V, T) triples) for the shading tests.
#include <glm/glm.hpp>

#include <cmath>
#include <numbers>
#include <random>

namespace hp::test {
inline glm::dvec3 uniformUnit(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0), a(0.0, 2.0 * std::numbers::pi);
  double z = u(rng), phi = a(rng), r = std::sqrt(1.0 - z * z);
  return {r * std::cos(phi), r * std::sin(phi), z};
}

struct Triple {
  glm::dvec3 L, V, T;
};
inline Triple uniformTriple(std::mt19937_64& rng) {
  Triple t;
  t.L = uniformUnit(rng);
  t.V = uniformUnit(rng);
  t.T = uniformUnit(rng);
  return t;
}
}  // namespace hp::test
