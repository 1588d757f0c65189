#pragma once
// Contract: the path tracer's random numbers and direction sampling. A Sampler is seeded from
// (seed, pixel, sample index) alone, so every pixel's estimate is the same whichever thread or tile
// order computes it. Directions come with their solid-angle densities.
#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

namespace hp::reference {
class Sampler {
 public:
  Sampler(std::uint64_t seed, std::uint64_t pixel, std::uint64_t sample)
      : state_(mix(mix(mix(seed) ^ pixel) ^ (sample * 0x9E3779B97F4A7C15ull))) {}
  // Uniform in [0, 1) with 53 random bits.
  double next() { return double(step() >> 11) * 0x1.0p-53; }

 private:
  static std::uint64_t mix(std::uint64_t z) {  // SplitMix64 finaliser
    z += 0x9E3779B97F4A7C15ull;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  std::uint64_t step() { return mix(state_ += 0x9E3779B97F4A7C15ull); }
  std::uint64_t state_;
};

inline constexpr double kPi = std::numbers::pi;

// Uniform on the unit sphere: density 1 / (4 pi).
inline glm::dvec3 uniformSphere(double u1, double u2) {
  const double z = 1.0 - 2.0 * u1, r = std::sqrt(std::max(0.0, 1.0 - z * z)), phi = 2.0 * kPi * u2;
  return {r * std::cos(phi), r * std::sin(phi), z};
}

// A standard normal from two uniforms (Box-Muller, one output).
inline double standardNormal(double u1, double u2) {
  return std::sqrt(-2.0 * std::log(std::max(u1, 1e-300))) * std::cos(2.0 * kPi * u2);
}

// A fibre's frame for sampling directions at it: T the unit tangent, U the eye's azimuth (phi = 0; any
// normal to T when the eye looks along it), W = T x U; sinR = sin theta_r of the eye (Marschner angles:
// sin theta = dot(direction, T)).
struct FibreFrame {
  glm::dvec3 T, U, W;
  double sinR = 0.0;

  FibreFrame(const glm::dvec3& tangent, const glm::dvec3& toEye) : T(glm::normalize(tangent)) {
    const glm::dvec3 v = glm::normalize(toEye);
    sinR = std::clamp(glm::dot(v, T), -1.0, 1.0);
    glm::dvec3 u = v - sinR * T;
    if (glm::dot(u, u) < 1e-20) u = glm::cross(T, std::abs(T.x) > 0.5 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0));
    U = glm::normalize(u);
    W = glm::cross(T, U);
  }
  // The direction at (sin theta, cos theta, phi), and a direction's sin theta and phi in [-pi, pi].
  glm::dvec3 direction(double sinTheta, double cosTheta, double phi) const {
    return sinTheta * T + cosTheta * (std::cos(phi) * U + std::sin(phi) * W);
  }
  double sinThetaOf(const glm::dvec3& dir) const { return std::clamp(glm::dot(dir, T), -1.0, 1.0); }
  double phiOf(const glm::dvec3& dir) const { return std::atan2(glm::dot(dir, W), glm::dot(dir, U)); }
};

// Cosine-weighted about the unit normal n: density cos / pi.
inline glm::dvec3 cosineHemisphere(const glm::dvec3& n, double u1, double u2) {
  const glm::dvec3 a = std::abs(n.x) > 0.5 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
  const glm::dvec3 t = glm::normalize(glm::cross(a, n)), b = glm::cross(n, t);
  const double r = std::sqrt(u1), phi = 2.0 * kPi * u2;
  return r * std::cos(phi) * t + r * std::sin(phi) * b + std::sqrt(std::max(0.0, 1.0 - u1)) * n;
}
}  // namespace hp::reference
