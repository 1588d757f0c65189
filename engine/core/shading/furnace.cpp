#include "engine/core/shading/furnace.h"

#include <cmath>
#include <vector>

#include "engine/core/shading/marschner.h"
#include "engine/core/shading/physical.h"
#include "engine/core/shading/quadrature.h"

namespace hp {
namespace {
constexpr double kPi = 3.14159265358979323846;

glm::dvec3 marschnerFurnaceOver(double sinThetaR, const HairMaterial& m, double phiLo, double phiHi, int panels) {
  glm::dvec3 sum(0.0);
  shading::gaussLegendre(-0.5 * kPi, 0.5 * kPi, panels, [&](double ti, double wt) {
    double s = std::sin(ti), c = std::cos(ti);
    shading::gaussLegendre(phiLo, phiHi, panels, [&](double phi, double wp) {
      sum += 2.0 * wt * wp * c * c * marschnerS(s, sinThetaR, std::cos(phi), m);
    });
  });
  return sum;
}
}  // namespace

std::array<glm::dvec3, 3> physicalLobeFurnaceOver(double sinThetaR, const HairMaterial& m, double phiLo,
                                                  double phiHi, int panels) {
  m.validate();
  double mInt[3] = {0, 0, 0};
  shading::gaussLegendre(-0.5 * kPi, 0.5 * kPi, 2 * panels, [&](double ti, double w) {
    double s = std::sin(ti), c = std::cos(ti);
    for (int p = 0; p < 3; ++p) mInt[p] += w * c * shading::physicalM(p, s, sinThetaR, m);
  });
  const shading::PhysicalN nInt = shading::physicalNIntegral(sinThetaR, m, phiLo, phiHi, panels);
  return {glm::dvec3(mInt[0] * nInt.r), mInt[1] * nInt.tt, mInt[2] * (nInt.trt + nInt.res)};
}

glm::dvec3 physicalFurnaceOver(double sinThetaR, const HairMaterial& m, double phiLo, double phiHi, int panels) {
  const auto lobes = physicalLobeFurnaceOver(sinThetaR, m, phiLo, phiHi, panels);
  return lobes[0] + lobes[1] + lobes[2];
}

glm::dvec3 whiteFurnace(FibreModel model, double sinThetaR, const HairMaterial& m, int panels) {
  // N is even in phi: int over [-pi, pi] = 2 int over [0, pi].
  return whiteFurnaceOver(model, sinThetaR, m, 0.0, kPi, panels);
}

glm::dvec3 whiteFurnaceOver(FibreModel model, double sinThetaR, const HairMaterial& m, double phiLo, double phiHi,
                            int panels) {
  m.validate();
  return model == FibreModel::Physical ? physicalFurnaceOver(sinThetaR, m, phiLo, phiHi, panels)
                                       : marschnerFurnaceOver(sinThetaR, m, phiLo, phiHi, panels);
}

glm::dvec3 skyAlbedoOver(FibreModel model, const HairMaterial& m, double phiLo, double phiHi) {
  const int panels = model == FibreModel::Physical ? 16 : 4;
  glm::dvec3 sum(0.0);
  shading::gaussLegendre(-0.5 * kPi, 0.5 * kPi, 2, [&](double thetaR, double w) {
    sum += 0.5 * w * std::cos(thetaR) * whiteFurnaceOver(model, std::sin(thetaR), m, phiLo, phiHi, panels);
  });
  return sum;
}

glm::dvec3 skyAlbedo(FibreModel model, const HairMaterial& m) { return skyAlbedoOver(model, m, 0.0, kPi); }
}  // namespace hp
