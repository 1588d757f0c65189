#include "samples/tools/reference/physical_sampling.h"

#include <algorithm>
#include <cmath>

#include "engine/core/shading/physical_terms.h"
#include "engine/core/shading/quadrature.h"

namespace hp::reference {
namespace {
constexpr int kResidual = 3;

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
    : frame_(tangent, toEye), material_(material) {
  const shading::PhysicalFibre fibre = shading::physicalFibre(frame_.sinR, material);
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
  const double sinR = frame_.sinR, cosR = std::sqrt(std::max(0.0, 1.0 - sinR * sinR));
  const double sinRp = sinR * std::cos(s) - cosR * std::sin(s), cosRp = std::abs(cosR * std::cos(s) + sinR * std::sin(s));
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
                                    : shading::physicalPhi(p, n.gammaO, n.gammaT) + material_.betaN * standardNormal(u3, u4);
  return frame_.direction(sinI, cosI, phi);
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
  const double sinI = frame_.sinThetaOf(dir);
  const double phi = frame_.phiOf(dir);
  double density = 0.0;
  for (int p = 0; p < 4; ++p)
    density += shading::physicalM(std::min(p, 2), sinI, frame_.sinR, material_) * azimuthDensity(p, phi);
  return density;
}
}  // namespace hp::reference
