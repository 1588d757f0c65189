#include "engine/core/shading/physical.h"

#include <algorithm>
#include <cmath>

#include "engine/core/shading/marschner.h"

namespace hp {
glm::dvec3 PhysicalLobes::total() const {
  glm::dvec3 sum = mR * n.r + mTT * n.tt + mTRT * (n.trt + n.res);
  return sum / std::max(cosThetaI, kPhysicalMinCosThetaI);
}

PhysicalLobes physicalLobes(double sinThetaI, double sinThetaR, double cosPhi, const HairMaterial& m) {
  PhysicalLobes l;
  l.mR = shading::physicalM(0, sinThetaI, sinThetaR, m);
  l.mTT = shading::physicalM(1, sinThetaI, sinThetaR, m);
  l.mTRT = shading::physicalM(2, sinThetaI, sinThetaR, m);
  l.n = shading::physicalN(std::acos(std::clamp(cosPhi, -1.0, 1.0)), sinThetaR, m);
  l.cosThetaI = std::sqrt(std::max(0.0, 1.0 - sinThetaI * sinThetaI));
  return l;
}

glm::dvec3 physicalS(double sinThetaI, double sinThetaR, double cosPhi, const HairMaterial& m) {
  return physicalLobes(sinThetaI, sinThetaR, cosPhi, m).total();
}

glm::dvec3 physicalS(glm::dvec3 L, glm::dvec3 V, glm::dvec3 T, const HairMaterial& m) {
  ShadingAngles a = shadingAngles(L, V, T);
  return physicalS(a.sinThetaI, a.sinThetaR, a.cosPhi, m);
}
}  // namespace hp
