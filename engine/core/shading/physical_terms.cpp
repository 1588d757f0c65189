// Factors of the energy-conserving fibre model; see physical_terms.h for the conventions.
#include "engine/core/shading/physical_terms.h"
#include "engine/core/shading/math_constants.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "engine/core/shading/fresnel.h"
#include "engine/core/shading/quadrature.h"

namespace hp::shading {
namespace {
double safeCos(double s) { return std::max(std::sqrt(std::max(0.0, 1.0 - s * s)), kPhysicalMinCos); }
}  // namespace

double logBesselI0(double x) {
  x = std::abs(x);
  // Both series below have positive terms only (no cancellation: ~1e-15 relative), and they are 10x faster
  // than std::cyl_bessel_i, which took a third of a physical LUT's build.
  if (x < 25.0) {  // I0(x) = sum_k (x^2 / 4)^k / (k!)^2
    const double q = 0.25 * x * x;
    double term = 1.0, sum = 1.0;
    for (int k = 1; term > 1e-17 * sum; ++k) {
      term *= q / (double(k) * double(k));
      sum += term;
    }
    return std::log(sum);
  }
  // Asymptotic: I0(x) = e^x / sqrt(2 pi x) sum_k ((2k - 1)!!)^2 / (k! (8x)^k). Its terms shrink until
  // k ~ 2x, the smallest below e^-2x (2e-22 at x = 25): summed until they fall under 1e-17 of the sum.
  const double r = 1.0 / (8.0 * x);
  double term = 1.0, sum = 1.0;
  for (int k = 1; k < 200; ++k) {
    const double next = term * double(2 * k - 1) * double(2 * k - 1) * r / double(k);
    if (next < 1e-17 * sum || next > term) break;
    term = next;
    sum += term;
  }
  return x - 0.5 * std::log(2.0 * kPi * x) + std::log(sum);
}

namespace {
// log of d'Eon's normalisation csch(1/v) / (2v) = e^{-1/v} / (v (1 - e^{-2/v})), in logs so that small v cannot
// overflow.
double deonLogNorm(double v) { return -1.0 / v - std::log(v) - std::log1p(-std::exp(-2.0 / v)); }

double deonMWithNorm(double v, double logNorm, double sinI, double cosI, double sinR, double cosR) {
  double a = cosI * cosR / v, b = sinI * sinR / v;
  return std::exp(logBesselI0(a) - b + logNorm);
}
}  // namespace

double deonM(double v, double sinI, double cosI, double sinR, double cosR) {
  return deonMWithNorm(v, deonLogNorm(v), sinI, cosI, sinR, cosR);
}

double physicalVariance(int p, const HairMaterial& m) {
  double vR = 4.0 * m.betaR * m.betaR;
  return p == 0 ? vR : p == 1 ? 0.25 * vR : 4.0 * vR;
}

double physicalShift(int p, const HairMaterial& m) {
  return p == 0 ? 2.0 * m.alphaR : p == 1 ? -m.alphaR : -4.0 * m.alphaR;
}

namespace {
double cosOfSin(double s) { return std::sqrt(std::max(0.0, 1.0 - s * s)); }  // unfloored, unlike safeCos

// sin and |cos| of theta_r - s_p, lobe p's shifted outgoing angle.
glm::dvec2 shiftedOutgoing(int p, double sinThetaR, const HairMaterial& m) {
  double s = physicalShift(p, m);
  double cosR = cosOfSin(sinThetaR);
  return {sinThetaR * std::cos(s) - cosR * std::sin(s), std::abs(cosR * std::cos(s) + sinThetaR * std::sin(s))};
}
}  // namespace

double physicalM(int p, double sinThetaI, double sinThetaR, const HairMaterial& m) {
  const glm::dvec2 r = shiftedOutgoing(p, sinThetaR, m);
  return deonM(physicalVariance(p, m), sinThetaI, cosOfSin(sinThetaI), r.x, r.y);
}

void physicalMRow(int p, double sinThetaR, const HairMaterial& m, const double* sinThetaI, int count, double* out) {
  const glm::dvec2 r = shiftedOutgoing(p, sinThetaR, m);
  const double v = physicalVariance(p, m), logNorm = deonLogNorm(v);
  for (int i = 0; i < count; ++i)
    out[i] = deonMWithNorm(v, logNorm, sinThetaI[i], cosOfSin(sinThetaI[i]), r.x, r.y);
}

PhysicalFibre physicalFibre(double sinThetaR, const HairMaterial& m) {
  PhysicalFibre f;
  f.eta = m.eta;
  f.cosTheta = safeCos(sinThetaR);
  f.etaPrime = std::sqrt(m.eta * m.eta - sinThetaR * sinThetaR) / f.cosTheta;
  double sinT = sinThetaR / m.eta;
  f.cosThetaT = std::sqrt(1.0 - sinT * sinT);
  f.sigma = m.absorption;
  return f;
}

PhysicalAttenuation physicalAttenuation(double h, const PhysicalFibre& f) {
  PhysicalAttenuation r;
  r.gammaO = std::asin(std::clamp(h, -1.0, 1.0));
  r.gammaT = std::asin(std::clamp(h / f.etaPrime, -1.0, 1.0));
  // Unpolarised dielectric reflectance at the true incidence angle, cos = cos theta cos gamma_o;
  // the internal reflections have the same value (reciprocity), so sum_p A_p = 1 without absorption.
  double incidence = std::acos(std::clamp(f.cosTheta * std::cos(r.gammaO), 0.0, 1.0));
  double fr = fresnel(f.eta, f.eta, incidence);
  glm::dvec3 t = glm::exp(-2.0 * f.sigma * std::cos(r.gammaT) / f.cosThetaT);
  r.a[0] = glm::dvec3(fr);
  r.a[1] = (1.0 - fr) * (1.0 - fr) * t;
  r.a[2] = r.a[1] * t * fr;
  r.a[3] = r.a[2] * fr * t / (1.0 - fr * t);
  return r;
}

double physicalPhi(int p, double gammaO, double gammaT) {
  return 2.0 * p * gammaT - 2.0 * gammaO + p * kPi;
}

double wrappedGaussian(double sigma, double x) {
  x -= 2.0 * kPi * std::nearbyint(x / (2.0 * kPi));  // [-pi, pi] (std::remainder: 5x slower, a third of N's build)
  double sum = 0.0, cut = 12.0 * sigma;
  for (int k = -2; k <= 2; ++k) {
    double y = x + 2.0 * kPi * k;
    if (std::abs(y) < cut) sum += std::exp(-y * y / (2.0 * sigma * sigma));  // beyond: < e^-72
  }
  return sum / (sigma * std::sqrt(2.0 * kPi));
}

void physicalNRow(double sinThetaR, const HairMaterial& m, const double* phis, int count, PhysicalN* out) {
  struct Node {
    double weight;
    PhysicalAttenuation a;
  };
  PhysicalFibre f = physicalFibre(sinThetaR, m);
  std::vector<Node> nodes;
  nodes.reserve(kPhysicalAzimuthPanels * 8);
  // h = sin gamma_o, dh = cos gamma_o d gamma_o: smooth integrand in gamma_o.
  gaussLegendre(-0.5 * kPi, 0.5 * kPi, kPhysicalAzimuthPanels, [&](double g, double w) {
    nodes.push_back({0.5 * w * std::cos(g), physicalAttenuation(std::sin(g), f)});
  });
  glm::dvec3 res(0.0);
  for (const Node& n : nodes) res += n.weight * n.a.a[3] / (2.0 * kPi);
  for (int k = 0; k < count; ++k) {
    PhysicalN& o = out[k];
    o = PhysicalN{};
    o.res = res;
    for (const Node& n : nodes) {
      o.r += n.weight * n.a.a[0].x * wrappedGaussian(m.betaN, phis[k] - physicalPhi(0, n.a.gammaO, n.a.gammaT));
      o.tt += n.weight * n.a.a[1] * wrappedGaussian(m.betaN, phis[k] - physicalPhi(1, n.a.gammaO, n.a.gammaT));
      o.trt += n.weight * n.a.a[2] * wrappedGaussian(m.betaN, phis[k] - physicalPhi(2, n.a.gammaO, n.a.gammaT));
    }
  }
}

PhysicalN physicalN(double phi, double sinThetaR, const HairMaterial& m) {
  PhysicalN n;
  physicalNRow(sinThetaR, m, &phi, 1, &n);
  return n;
}

PhysicalN physicalNIntegral(double sinThetaR, const HairMaterial& m, double phiLo, double phiHi, int panels) {
  std::vector<double> phis, weights;
  gaussLegendre(phiLo, phiHi, panels, [&](double phi, double w) {
    phis.push_back(phi);
    weights.push_back(2.0 * w);
  });
  std::vector<PhysicalN> n(phis.size());
  physicalNRow(sinThetaR, m, phis.data(), int(phis.size()), n.data());
  PhysicalN sum;
  for (std::size_t k = 0; k < n.size(); ++k) {
    sum.r += weights[k] * n[k].r;
    sum.tt += weights[k] * n[k].tt;
    sum.trt += weights[k] * n[k].trt;
    sum.res += weights[k] * n[k].res;
  }
  return sum;
}

std::array<glm::dvec3, kPhysicalLobes> physicalLobeEnergy(double sinThetaR, const HairMaterial& m) {
  PhysicalFibre f = physicalFibre(sinThetaR, m);
  std::array<glm::dvec3, kPhysicalLobes> e{};
  gaussLegendre(-0.5 * kPi, 0.5 * kPi, kPhysicalAzimuthPanels, [&](double g, double w) {
    PhysicalAttenuation a = physicalAttenuation(std::sin(g), f);
    for (int p = 0; p < kPhysicalLobes; ++p) e[p] += 0.5 * w * std::cos(g) * a.a[p];
  });
  return e;
}
}  // namespace hp::shading
