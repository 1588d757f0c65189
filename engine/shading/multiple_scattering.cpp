#include "engine/shading/multiple_scattering.h"

#include <algorithm>
#include <cmath>

#include "engine/error.h"
#include "engine/shading/math_constants.h"
#include "engine/shading/physical_terms.h"
#include "engine/shading/quadrature.h"

namespace hp {
namespace {
constexpr int kPanels = 16;

// int M_p(theta_i, theta) cos theta_i d theta_i over [-pi/2, pi/2], for R, TT, TRT.
glm::dvec3 longitudinalIntegrals(double sinTheta, const HairMaterial& m) {
  glm::dvec3 sum(0.0);
  shading::gaussLegendre(-0.5 * shading::kPi, 0.5 * shading::kPi, 2 * kPanels, [&](double ti, double w) {
    const double s = std::sin(ti), c = std::cos(ti);
    for (int p = 0; p < 3; ++p) sum[p] += w * c * shading::physicalM(p, s, sinTheta, m);
  });
  return sum;
}

}  // namespace

MultipleScatteringTables multipleScatteringTables(const HairMaterial& m, int entries) {
  if (entries < 2 || entries > 1024) throw Error("multiple scattering tables: entries must be in [2, 1024]");
  m.validate();
  MultipleScatteringTables t;
  for (int k = 0; k < entries; ++k) {
    const double s = std::clamp(-1.0 + 2.0 * k / (entries - 1), -kEdgeSine, kEdgeSine);
    const glm::dvec3 mInt = longitudinalIntegrals(s, m);
    const shading::PhysicalN far = shading::physicalNIntegral(s, m, 0.5 * shading::kPi, shading::kPi, kPanels);
    t.forwardAlbedo.push_back(mInt[0] * far.r + mInt[1] * far.tt + mInt[2] * (far.trt + far.res));
    const auto energy = shading::physicalLobeEnergy(s, m);  // int N_p d phi over the whole circle
    t.meanR.push_back(energy[0].x / (2.0 * shading::kPi));
    t.meanTT.push_back(energy[1] / (2.0 * shading::kPi));
    t.meanTRT.push_back((energy[2] + energy[3]) / (2.0 * shading::kPi));
  }
  return t;
}
}  // namespace hp
