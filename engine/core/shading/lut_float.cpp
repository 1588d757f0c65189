// `float` mode LUT: M over the signed pseudo-angle of theta_h (1D), N0/N1 over (pseudo-angle of
// phi/2, pseudo-angle of |theta_d|). See shaders/shared/marschner.h for the shader side.
#include <algorithm>
#include <cmath>

#include "engine/core/shading/lut.h"
#include "engine/core/shading/lut_texture.h"
#include "engine/core/shading/marschner.h"
#include "engine/core/shading/marschner_terms.h"
#include "shaders/shared/marschner.h"

namespace hp {
namespace {
using shading::makeLutTexture;

float quantise(double v, LutFormat f) { return shading::quantiseTexel(v, f); }

LutTexture buildFloatM(const HairMaterial& m, LutFormat f) {
  LutTexture t = makeLutTexture("M", gpu::MARSCHNER_FLOAT_M_WIDTH, 1, f);
  t.channelNames = {"M_R", "M_TT", "M_TRT", "unused"};
  t.uAxis = "signed pseudo-angle of theta_h: 0.5 + 0.5 sign(theta_h) P(|theta_h|), texel-centre mapped";
  t.vAxis = "none (height 1)";
  for (std::uint32_t i = 0; i < t.width; ++i) {
    double w = 2.0 * shading::texelCentre(i, t.width) - 1.0;
    double thetaH = std::copysign(shading::pseudoAngleInverse(std::abs(w)), w);
    float* px = t.texel(i, 0);
    for (int p = 0; p < 3; ++p) px[p] = quantise(shading::lobeM(p, thetaH, m), f);
  }
  return t;
}

void buildFloatN(const HairMaterial& m, LutTexture& n0, LutTexture& n1) {
  double limit = std::acos(kMinCosThetaD);
  for (std::uint32_t j = 0; j < n0.height; ++j) {
    double thetaD = std::min(shading::pseudoAngleInverse(shading::texelCentre(j, n0.height)), limit);
    for (std::uint32_t i = 0; i < n0.width; ++i) {
      double phi = 2.0 * shading::pseudoAngleInverse(shading::texelCentre(i, n0.width));
      glm::dvec3 tt = shading::lobeNTT(phi, thetaD, m);
      glm::dvec3 trt = shading::lobeNTRT(phi, thetaD, m);
      float* a = n0.texel(i, j);
      float* b = n1.texel(i, j);
      for (int c = 0; c < 3; ++c) {
        a[c] = quantise(tt[c], n0.format);
        b[c] = quantise(trt[c], n1.format);
      }
      a[3] = quantise(shading::lobeNR(phi, thetaD, m), n0.format);
    }
  }
}
}  // namespace

MarschnerLut buildFloatLut(const HairMaterial& material, LutFormat format) {
  material.validate();
  MarschnerLut lut;
  lut.mode = LutMode::Float;
  lut.material = material;
  const char* nu = "pseudo-angle P(phi/2): 0 at phi = 0, 1 at phi = pi, texel-centre mapped";
  const char* nv = "pseudo-angle P(|theta_d|): 0 at theta_d = 0, 1 at 90 deg, texel-centre mapped";
  LutTexture n0 = makeLutTexture("N0", gpu::MARSCHNER_FLOAT_N_WIDTH, gpu::MARSCHNER_FLOAT_N_HEIGHT, format);
  LutTexture n1 = makeLutTexture("N1", gpu::MARSCHNER_FLOAT_N_WIDTH, gpu::MARSCHNER_FLOAT_N_HEIGHT, format);
  n0.channelNames = {"N_TT.r", "N_TT.g", "N_TT.b", "N_R"};
  n1.channelNames = {"N_TRT.r", "N_TRT.g", "N_TRT.b", "unused"};
  n0.uAxis = n1.uAxis = nu;
  n0.vAxis = n1.vAxis = nv;
  buildFloatN(material, n0, n1);
  lut.textures = {buildFloatM(material, format), std::move(n0), std::move(n1)};
  lut.parameterisation =
      "P(a) = sin(a)/sqrt2 for a <= pi/4, 1 - cos(a)/sqrt2 above, computed from cos(2a) with square "
      "roots only; x in [0,1] -> texture coordinate (x (n-1) + 0.5)/n. "
      "S = (M_R N_R + M_TT N_TT + M_TRT N_TRT) * 2 / (1 + cos 2 theta_d), cos 2 theta_d = "
      "cos theta_i cos theta_r + sin theta_i sin theta_r.";
  return lut;
}
}  // namespace hp
