#include "samples/tools/reference/fibre_sampling.h"

#include <algorithm>
#include <cmath>

namespace hp::reference {
namespace {
constexpr double kUniformShare = 0.2;
constexpr double kLobeShare[3] = {0.4, 0.3, 0.3};  // R, TT, TRT
constexpr double kPhiUniformShare = 0.5;
constexpr double kPhiWidth = 0.4;  // radians, the transmission peak's width

double gaussian(double x, double sigma) {
  return std::exp(-0.5 * x * x / (sigma * sigma)) / (sigma * std::sqrt(2.0 * kPi));
}

double wrapPi(double x) { return x - 2.0 * kPi * std::floor((x + kPi) / (2.0 * kPi)); }
}  // namespace

FibreSampler::FibreSampler(const glm::dvec3& tangent, const glm::dvec3& toEye, const HairMaterial& m)
    : frame_(tangent, toEye), thetaR_(std::asin(frame_.sinR)) {
  const double a = m.alphaR, b = m.betaR;
  shift_[0] = a, shift_[1] = -0.5 * a, shift_[2] = -1.5 * a;
  width_[0] = b, width_[1] = 0.5 * b, width_[2] = 2.0 * b;
}

glm::dvec3 FibreSampler::sample(Sampler& rng) const {
  const double pick = rng.next(), u1 = rng.next(), u2 = rng.next(), u3 = rng.next(), u4 = rng.next();
  if (pick < kUniformShare) return uniformSphere(u1, u2);
  const double lobePick = (pick - kUniformShare) / (1.0 - kUniformShare);
  const int p = lobePick < kLobeShare[0] ? 0 : lobePick < kLobeShare[0] + kLobeShare[1] ? 1 : 2;
  const double thetaH = shift_[p] + width_[p] * standardNormal(u1, u2);
  const double thetaI = 2.0 * thetaH - thetaR_;
  if (std::abs(thetaI) > 0.5 * kPi) return glm::dvec3(0.0);  // no direction: the sample carries nothing
  const double phi = u3 < kPhiUniformShare ? 2.0 * kPi * (u4 - 0.5)
                                           : wrapPi(kPi + kPhiWidth * standardNormal(u4, rng.next()));
  return frame_.direction(std::sin(thetaI), std::cos(thetaI), phi);
}

double FibreSampler::longitudinalPdf(double thetaI) const {
  const double thetaH = 0.5 * (thetaI + thetaR_);
  double sum = 0.0;
  for (int p = 0; p < 3; ++p) sum += kLobeShare[p] * gaussian(thetaH - shift_[p], width_[p]);
  return 0.5 * sum;  // d theta_h / d theta_i = 1/2
}

double FibreSampler::azimuthPdf(double phi) const {
  double peak = 0.0;
  for (int k = -1; k <= 1; ++k) peak += gaussian(phi - kPi + 2.0 * kPi * k, kPhiWidth);  // wrapped to [-pi, pi)
  return kPhiUniformShare / (2.0 * kPi) + (1.0 - kPhiUniformShare) * peak;
}

double FibreSampler::pdf(const glm::dvec3& dir) const {
  const double s = frame_.sinThetaOf(dir);
  const double thetaI = std::asin(s), cosI = std::sqrt(1.0 - s * s);
  const double phi = frame_.phiOf(dir);
  const double lobes = cosI > 1e-12 ? longitudinalPdf(thetaI) * azimuthPdf(phi) / cosI : 0.0;
  return kUniformShare / (4.0 * kPi) + (1.0 - kUniformShare) * lobes;
}
}  // namespace hp::reference
