#include "engine/core/shading/marschner_terms.h"
#include "engine/core/shading/math_constants.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "engine/core/shading/azimuth.h"
#include "engine/core/shading/fresnel.h"

namespace hp::shading {
namespace {
double wrapPi(double x) { return x - 2.0 * kPi * std::floor((x + kPi) / (2.0 * kPi)); }

double smoothstep(double e0, double e1, double x) {
  double t = std::clamp((x - e0) / (e1 - e0), 0.0, 1.0);
  return t * t * (3.0 - 2.0 * t);
}
}  // namespace

double gaussian(double beta, double x) {
  return std::exp(-x * x / (2.0 * beta * beta)) / (beta * std::sqrt(2.0 * kPi));
}

double longitudinalAlpha(int p, const HairMaterial& m) {
  const double f[3] = {1.0, -0.5, -1.5};
  return f[p] * m.alphaR;
}

double longitudinalBeta(int p, const HairMaterial& m) {
  const double f[3] = {1.0, 0.5, 2.0};
  return f[p] * m.betaR;
}

double lobeM(int p, double thetaH, const HairMaterial& m) {
  return gaussian(longitudinalBeta(p, m), thetaH - longitudinalAlpha(p, m));
}

double bravaisEtaPrime(double eta, double thetaD) {
  double s = std::sin(thetaD);
  return std::sqrt(eta * eta - s * s) / std::max(std::cos(thetaD), 1e-300);
}

double bravaisEtaDoublePrime(double eta, double thetaD) {
  double s = std::sin(thetaD);
  return eta * eta * std::cos(thetaD) / std::sqrt(eta * eta - s * s);
}

glm::dvec3 attenuation(int p, double gammaI, double thetaD, const HairMaterial& m) {
  double e1 = bravaisEtaPrime(m.eta, thetaD);
  double e2 = bravaisEtaDoublePrime(m.eta, thetaD);
  double f = fresnel(e1, e2, gammaI);
  if (p == 0) return glm::dvec3(f);
  double gammaT = std::asin(std::clamp(std::sin(gammaI) / e1, -1.0, 1.0));
  double sinThetaT = std::sin(thetaD) / m.eta;
  double cosThetaT = std::sqrt(1.0 - sinThetaT * sinThetaT);
  glm::dvec3 transmit = glm::exp(-2.0 * (m.absorption / cosThetaT) * std::cos(gammaT));
  double internal = p > 1 ? std::pow(fresnel(1.0 / e1, 1.0 / e2, gammaT), p - 1) : 1.0;
  glm::dvec3 tp(1.0);
  for (int i = 0; i < p; ++i) tp *= transmit;
  return (1.0 - f) * (1.0 - f) * internal * tp;
}

glm::dvec3 lobeNRaw(int p, double phi, double thetaD, const HairMaterial& m) {
  double etaP = bravaisEtaPrime(m.eta, thetaD);
  AzimuthRoots roots = azimuthRoots(p, etaP, phi);
  glm::dvec3 sum(0.0);
  for (std::size_t i = 0; i < roots.count; ++i) {
    double g = roots.gamma[i];
    double dPhi = std::max(std::abs(dPhiCubicDGamma(p, g, etaP)), kMinDPhi);
    // |2 dPhi/dh| = 2 |dPhi/dgamma| / cos gamma
    sum += attenuation(p, g, thetaD, m) * std::cos(g) / (2.0 * dPhi);
  }
  return sum;
}

double lobeNR(double phi, double thetaD, const HairMaterial& m) { return lobeNRaw(0, phi, thetaD, m).x; }

glm::dvec3 lobeNTT(double phi, double thetaD, const HairMaterial& m) {
  return lobeNRaw(1, phi, thetaD, m);
}

TrtCaustic trtCaustic(double thetaD, const HairMaterial& m) {
  TrtCaustic c;
  double etaP = bravaisEtaPrime(m.eta, thetaD);
  if (etaP < 2.0) {
    c.causticBranch = true;
    c.hc = std::sqrt((4.0 - etaP * etaP) / 3.0);
    c.phic = phiExactTRT(c.hc, etaP);
    double d2 = std::abs(d2PhiExactTRTdH2(c.hc, etaP));
    c.dh = d2 > 0.0 ? std::min(m.dhM, 2.0 * std::sqrt(2.0 * m.wc / d2)) : m.dhM;
    c.t = 1.0;
  } else {
    c.hc = 0.0;
    c.phic = 0.0;
    c.dh = m.dhM;
    c.t = 1.0 - smoothstep(2.0, 2.0 + m.dEta, etaP);
  }
  return c;
}

glm::dvec3 lobeNTRT(double phi, double thetaD, const HairMaterial& m) {
  glm::dvec3 n = lobeNRaw(2, phi, thetaD, m);
  TrtCaustic c = trtCaustic(thetaD, m);
  double dm = wrapPi(phi - c.phic);
  double dp = wrapPi(phi + c.phic);
  double g0 = gaussian(m.wc, 0.0);
  double gm = gaussian(m.wc, dm);
  double gp = gaussian(m.wc, dp);
  n *= (1.0 - c.t * gm / g0) * (1.0 - c.t * gp / g0);
  glm::dvec3 ac = attenuation(2, std::asin(c.hc), thetaD, m);
  return n + c.t * m.kG * ac * c.dh * (gm + gp);
}
}  // namespace hp::shading
