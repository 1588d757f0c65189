#include "samples/tools/reference/physical_sampling.h"

#include <algorithm>
#include <cmath>

#include "engine/core/shading/physical_terms.h"
#include "engine/core/shading/quadrature.h"

namespace hp::reference {
namespace {
constexpr int kResidual = 3;

double normal(double u1, double u2) {  // Box-Muller, one output
  return std::sqrt(-2.0 * std::log(std::max(u1, 1e-300))) * std::cos(2.0 * kPi * u2);
}

int pick(const double* probabilities, int count, double u) {
  for (int p = 0; p < count - 1; ++p) {
    if (u < probabilities[p]) return p;
    u -= probabilities[p];
  }
  return count - 1;
}
}  // namespace

PhysicalFibreSampler::PhysicalFibreSampler(const glm::dvec3& tangent, const glm::dvec3& toEye,
                                           const HairMaterial& material)
    : T_(glm::normalize(tangent)), material_(material) {
  const glm::dvec3 v = glm::normalize(toEye);
  sinR_ = std::clamp(glm::dot(v, T_), -1.0, 1.0);
  glm::dvec3 u = v - sinR_ * T_;
  if (glm::dot(u, u) < 1e-20) u = glm::cross(T_, std::abs(T_.x) > 0.5 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0));
  U_ = glm::normalize(u);
  W_ = glm::cross(T_, U_);
  const shading::PhysicalFibre fibre = shading::physicalFibre(sinR_, material);
  double running = 0.0;
  shading::gaussLegendre(-0.5 * kPi, 0.5 * kPi, shading::kPhysicalAzimuthPanels, [&](double g, double w) {
    const shading::PhysicalAttenuation a = shading::physicalAttenuation(std::sin(g), fibre);
    Node n{a.gammaO, a.gammaT, {}};
    double total = 0.0;
    for (int p = 0; p < 4; ++p) total += n.lobe[p] = (a.a[p].x + a.a[p].y + a.a[p].z) / 3.0;
    for (double& l : n.lobe) l = total > 0.0 ? l / total : 0.25;
    nodes_.push_back(n);
    weights_.push_back(0.5 * w * std::cos(g));
    running += weights_.back();
    cumulative_.push_back(running);
  });
}

// d'Eon's lobe sampled exactly (cos of the angle to the shifted specular cone, then its azimuth about it).
double PhysicalFibreSampler::sampleSinThetaI(int p, double u1, double u2) const {
  const int q = std::min(p, 2);  // the residual's longitudinal lobe is TRT's
  const double v = shading::physicalVariance(q, material_), s = shading::physicalShift(q, material_);
  const double cosR = std::sqrt(std::max(0.0, 1.0 - sinR_ * sinR_));
  const double sinRp = sinR_ * std::cos(s) - cosR * std::sin(s), cosRp = std::abs(cosR * std::cos(s) + sinR_ * std::sin(s));
  const double cosTheta = std::clamp(1.0 + v * std::log(std::max(u1, 1e-300) + (1.0 - u1) * std::exp(-2.0 / v)), -1.0, 1.0);
  const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
  return std::clamp(-cosTheta * sinRp + sinTheta * std::cos(2.0 * kPi * u2) * cosRp, -1.0, 1.0);
}

glm::dvec3 PhysicalFibreSampler::sample(Sampler& rng) const {
  const double uNode = rng.next() * cumulative_.back();
  const auto k = std::size_t(std::upper_bound(cumulative_.begin(), cumulative_.end(), uNode) - cumulative_.begin());
  const Node& n = nodes_[std::min(k, nodes_.size() - 1)];
  const int p = pick(n.lobe.data(), 4, rng.next());
  const double u1 = rng.next(), u2 = rng.next();
  const double sinI = sampleSinThetaI(p, u1, u2), cosI = std::sqrt(std::max(0.0, 1.0 - sinI * sinI));
  const double u3 = rng.next(), u4 = rng.next();
  const double phi = p == kResidual ? 2.0 * kPi * u3
                                    : shading::physicalPhi(p, n.gammaO, n.gammaT) + material_.betaN * normal(u3, u4);
  return sinI * T_ + cosI * (std::cos(phi) * U_ + std::sin(phi) * W_);
}

double PhysicalFibreSampler::azimuthDensity(int p, double phi) const {
  double sum = 0.0;
  for (std::size_t k = 0; k < nodes_.size(); ++k) {
    const Node& n = nodes_[k];
    if (n.lobe[p] == 0.0) continue;
    const double g = p == kResidual ? 1.0 / (2.0 * kPi)
                                    : shading::wrappedGaussian(material_.betaN, phi - shading::physicalPhi(p, n.gammaO, n.gammaT));
    sum += weights_[k] * n.lobe[p] * g;
  }
  return sum / cumulative_.back();
}

double PhysicalFibreSampler::pdf(const glm::dvec3& dir) const {
  const double sinI = std::clamp(glm::dot(dir, T_), -1.0, 1.0);
  const double phi = std::atan2(glm::dot(dir, W_), glm::dot(dir, U_));
  double density = 0.0;
  for (int p = 0; p < 4; ++p)
    density += shading::physicalM(std::min(p, 2), sinI, sinR_, material_) * azimuthDensity(p, phi);
  return density;
}
}  // namespace hp::reference
