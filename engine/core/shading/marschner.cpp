#include "engine/core/shading/marschner.h"

#include <algorithm>
#include <cmath>

#include "engine/core/shading/marschner_terms.h"

namespace hp {
ShadingAngles shadingAngles(glm::dvec3 L, glm::dvec3 V, glm::dvec3 T) {
  glm::dvec3 t = glm::normalize(T);
  glm::dvec3 l = glm::normalize(L);
  glm::dvec3 v = glm::normalize(V);
  ShadingAngles a;
  a.sinThetaI = std::clamp(glm::dot(l, t), -1.0, 1.0);
  a.sinThetaR = std::clamp(glm::dot(v, t), -1.0, 1.0);
  glm::dvec3 lp = l - a.sinThetaI * t;
  glm::dvec3 vp = v - a.sinThetaR * t;
  double d = glm::dot(lp, lp) * glm::dot(vp, vp);
  a.cosPhi = d > 1e-28 ? std::clamp(glm::dot(lp, vp) / std::sqrt(d), -1.0, 1.0) : 0.0;
  return a;
}

glm::dvec3 MarschnerLobes::total() const {
  return (mR * nR + mTT * nTT + mTRT * nTRT) / (cosThetaD * cosThetaD);
}

MarschnerLobes marschnerLobes(double sinThetaI, double sinThetaR, double cosPhi, const HairMaterial& m) {
  double ti = std::asin(std::clamp(sinThetaI, -1.0, 1.0));
  double tr = std::asin(std::clamp(sinThetaR, -1.0, 1.0));
  double thetaH = 0.5 * (ti + tr);
  double thetaD = 0.5 * (tr - ti);
  double limit = std::acos(kMinCosThetaD);
  thetaD = std::clamp(thetaD, -limit, limit);
  double phi = std::acos(std::clamp(cosPhi, -1.0, 1.0));
  MarschnerLobes lobes;
  lobes.mR = shading::lobeM(0, thetaH, m);
  lobes.mTT = shading::lobeM(1, thetaH, m);
  lobes.mTRT = shading::lobeM(2, thetaH, m);
  lobes.nR = shading::lobeNR(phi, thetaD, m);
  lobes.nTT = shading::lobeNTT(phi, thetaD, m);
  lobes.nTRT = shading::lobeNTRT(phi, thetaD, m);
  lobes.cosThetaD = std::cos(thetaD);
  return lobes;
}

glm::dvec3 marschnerS(double sinThetaI, double sinThetaR, double cosPhi, const HairMaterial& m) {
  return marschnerLobes(sinThetaI, sinThetaR, cosPhi, m).total();
}

glm::dvec3 marschnerS(glm::dvec3 L, glm::dvec3 V, glm::dvec3 T, const HairMaterial& m) {
  ShadingAngles a = shadingAngles(L, V, T);
  return marschnerS(a.sinThetaI, a.sinThetaR, a.cosPhi, m);
}
}  // namespace hp
