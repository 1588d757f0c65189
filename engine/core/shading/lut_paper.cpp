// `paper` mode LUT: the two RGBA8 128x128 textures of the paper / GPU Gems 2 ch. 23.
#include <algorithm>
#include <cmath>

#include "engine/core/shading/lut.h"
#include "engine/core/shading/marschner.h"
#include "engine/core/shading/marschner_terms.h"
#include "shaders/shared/marschner.h"

namespace hp {
namespace {
LutTexture makeTexture(const char* name, LutFormat format) {
  LutTexture t;
  t.name = name;
  t.width = t.height = gpu::MARSCHNER_PAPER_LUT_SIZE;
  t.format = format;
  t.data.assign(std::size_t(t.width) * t.height * 4, 0.0f);
  return t;
}

double centre(std::uint32_t i, std::uint32_t n) { return (i + 0.5) / n; }

// Rescales each channel by its maximum (so it fills [0, 1]) and quantises to 8 bits (RGBA8 only).
void normaliseToUnorm8(LutTexture& t, const std::array<bool, 4>& rescale) {
  bool quantise = t.format == LutFormat::RGBA8Unorm;
  for (int c = 0; c < 4; ++c) {
    float maxV = 0.0f;
    for (std::size_t k = c; k < t.data.size(); k += 4) maxV = std::max(maxV, t.data[k]);
    t.scale[c] = rescale[c] && maxV > 0.0f ? maxV : 1.0f;
    for (std::size_t k = c; k < t.data.size(); k += 4) {
      float v = std::clamp(t.data[k] / t.scale[c], 0.0f, 1.0f);
      t.data[k] = quantise ? std::nearbyint(v * 255.0f) / 255.0f : v;
    }
  }
}

LutTexture buildPaperM(const HairMaterial& m, LutFormat f) {
  LutTexture t = makeTexture("M", f);
  t.channelNames = {"M_R", "M_TT", "M_TRT", "cos_theta_d"};
  t.uAxis = "sin(theta_i) * 0.5 + 0.5";
  t.vAxis = "sin(theta_r) * 0.5 + 0.5";
  for (std::uint32_t j = 0; j < t.height; ++j)
    for (std::uint32_t i = 0; i < t.width; ++i) {
      double ti = std::asin(2.0 * centre(i, t.width) - 1.0);
      double tr = std::asin(2.0 * centre(j, t.height) - 1.0);
      double thetaH = 0.5 * (ti + tr);
      float* px = t.texel(i, j);
      for (int p = 0; p < 3; ++p) px[p] = static_cast<float>(shading::lobeM(p, thetaH, m));
      px[3] = static_cast<float>(std::cos(0.5 * (tr - ti)));
    }
  normaliseToUnorm8(t, {true, true, true, false});
  return t;
}

LutTexture buildPaperN(const HairMaterial& m, LutFormat f) {
  LutTexture t = makeTexture("N", f);
  t.channelNames = {"(N_TT + N_TRT).r", "(N_TT + N_TRT).g", "(N_TT + N_TRT).b", "N_R"};
  t.uAxis = "cos(phi) * 0.5 + 0.5";
  t.vAxis = "cos(theta_d)";
  for (std::uint32_t j = 0; j < t.height; ++j)
    for (std::uint32_t i = 0; i < t.width; ++i) {
      double phi = std::acos(2.0 * centre(i, t.width) - 1.0);
      double thetaD = std::acos(std::max(centre(j, t.height), kMinCosThetaD));
      glm::dvec3 colour = shading::lobeNTT(phi, thetaD, m) + shading::lobeNTRT(phi, thetaD, m);
      float* px = t.texel(i, j);
      for (int c = 0; c < 3; ++c) px[c] = static_cast<float>(colour[c]);
      px[3] = static_cast<float>(shading::lobeNR(phi, thetaD, m));
    }
  normaliseToUnorm8(t, {true, true, true, true});
  return t;
}
}  // namespace

MarschnerLut buildPaperLut(const HairMaterial& material, LutFormat format) {
  material.validate();
  MarschnerLut lut;
  lut.mode = LutMode::Paper;
  lut.material = material;
  lut.textures = {buildPaperM(material, format), buildPaperN(material, format)};
  lut.parameterisation =
      "paper: m = M(sin theta_i, sin theta_r) * mScale; n = N(cos phi, m.a) * nScale; "
      "S = (m.r n.a + m.g n.rgb) / m.a^2 (M_TT stands in for M_TRT)";
  return lut;
}
}  // namespace hp
