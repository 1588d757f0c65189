// `physical` mode LUT (docs/THEORY.md §4.6, the paper's two-texture structure): M over (signed
// pseudo-angle of theta_i, of theta_r), N0/N1 over (pseudo-angle of phi/2, of |theta_r|).
// Shader side: marschnerPhysicalCoords in shaders/shared/marschner.h, marschnerLutPhysical in
// shaders/marschner.glsl.
#include <algorithm>
#include <cmath>
#include <vector>

#include "engine/core/shading/lut.h"
#include "engine/core/shading/lut_texture.h"
#include "engine/core/shading/multiple_scattering.h"
#include "engine/core/shading/physical_terms.h"
#include "shaders/shared/marschner.h"
#include "shaders/shared/strands.h"

namespace hp {
namespace {
// sin theta at texel i of a signed pseudo-angle axis of n texels.
double signedAxisSine(std::uint32_t i, std::uint32_t n) {
  double w = 2.0 * shading::texelCentre(i, n) - 1.0;
  return std::copysign(std::sin(shading::pseudoAngleInverse(std::abs(w))), w);
}

// The local back-scattering's longitudinal lobe (multiple_scattering.h) in column i (theta_i): a Gaussian
// in theta_i + theta_r, normalised so that its sum over the column's texels against cos theta_r d theta_r is
// 1 (the lobe may reach past a pole; a lobe narrower than a texel lands on the nearest one). In the first layer's
// rows: buildM copies it to the others (the tables are the material's, not a strand's).
void fillBackLobe(LutTexture& t, const MultipleScatteringTables& tables, const std::vector<double>& theta) {
  const std::uint32_t n = t.width;
  std::vector<double> weight(n), g(n);  // cos theta_r d theta_r per texel, the lobe
  for (std::uint32_t j = 0; j < n; ++j) {
    const double lo = theta[j == 0 ? 0 : j - 1], hi = theta[j + 1 == n ? j : j + 1];
    weight[j] = std::cos(theta[j]) * (hi - lo) / (j == 0 || j + 1 == n ? 1.0 : 2.0);
  }
  for (std::uint32_t i = 0; i < n; ++i) {
    const glm::dvec2 lobe = backLobeAt(tables, std::sin(theta[i]));
    double sum = 0.0;
    for (std::uint32_t j = 0; j < n; ++j) {
      const double x = (theta[i] + theta[j] - lobe.x) / lobe.y;
      g[j] = std::exp(-0.5 * x * x);
      sum += g[j] * weight[j];
    }
    if (!(sum > 1e-200)) {  // nothing sampled: the whole lobe on the texel nearest its centre
      const double centre = std::clamp(lobe.x - theta[i], theta.front(), theta.back());
      const auto k = std::lower_bound(theta.begin(), theta.end(), centre) - theta.begin();
      std::fill(g.begin(), g.end(), 0.0);
      g[std::min<std::size_t>(k, n - 1)] = 1.0;
      sum = weight[std::min<std::size_t>(k, n - 1)];
    }
    for (std::uint32_t j = 0; j < n; ++j) t.texel(i, j)[3] = shading::quantiseTexel(g[j] / sum, t.format);
  }
}

// One n x n layer of M from row `row0`: the lobes of material m (a strand's beta_R already scaled).
void fillMLayer(LutTexture& t, const HairMaterial& m, std::uint32_t row0) {
  const std::uint32_t n = gpu::MARSCHNER_PHYSICAL_M_SIZE;
  std::vector<double> sines(n), row(n);
  for (std::uint32_t i = 0; i < n; ++i) sines[i] = signedAxisSine(i, n);
  for (std::uint32_t j = 0; j < n; ++j)
    for (int p = 0; p < 3; ++p) {
      shading::physicalMRow(p, sines[j], m, sines.data(), int(n), row.data());
      for (std::uint32_t i = 0; i < n; ++i) t.texel(i, row0 + j)[p] = shading::quantiseTexel(row[i], t.format);
    }
}

LutTexture buildM(const HairMaterial& m, const MultipleScatteringTables& tables, LutFormat f) {
  const std::uint32_t n = gpu::MARSCHNER_PHYSICAL_M_SIZE;
  const float variation = float(m.roughnessVariation);  // as the shader reads it (MarschnerParams.caustic.w)
  const std::uint32_t layers = gpu::marschnerPhysicalMLayers(variation);
  LutTexture t = shading::makeLutTexture("M", n, n * layers, f);
  t.channelNames = {"M_R", "M_TT", "M_TRT", "M_back (local back-scattering)"};
  t.uAxis = "signed pseudo-angle of theta_i: 0.5 + 0.5 sign P(|theta_i|), texel-centre mapped";
  t.vAxis = layers == 1 ? "signed pseudo-angle of theta_r, same map"
                        : "layer k of " + std::to_string(layers) + " (beta_R x (1 + V (2k / " + std::to_string(layers - 1) +
                              " - 1)), V the roughness variation) + the signed pseudo-angle of theta_r, same map, over " +
                              std::to_string(layers);
  std::vector<double> theta(n);
  for (std::uint32_t j = 0; j < n; ++j) theta[j] = std::asin(signedAxisSine(j, n));
  fillBackLobe(t, tables, theta);
  for (std::uint32_t k = 0; k < layers; ++k) {
    HairMaterial layer = m;
    if (layers > 1) layer.betaR = m.betaR * double(gpu::strandRoughnessOfLevel(k, variation));
    fillMLayer(t, layer, k * n);
    if (k == 0) continue;
    for (std::uint32_t j = 0; j < n; ++j)  // the same back lobe in every layer
      for (std::uint32_t i = 0; i < n; ++i) t.texel(i, k * n + j)[3] = t.texel(i, j)[3];
  }
  return t;
}

void buildN(const HairMaterial& m, LutTexture& n0, LutTexture& n1) {
  std::vector<double> phis(n0.width);
  for (std::uint32_t i = 0; i < n0.width; ++i)
    phis[i] = 2.0 * shading::pseudoAngleInverse(shading::texelCentre(i, n0.width));
  std::vector<shading::PhysicalN> row(n0.width);
  for (std::uint32_t j = 0; j < n0.height; ++j) {
    double sr = std::sin(shading::pseudoAngleInverse(shading::texelCentre(j, n0.height)));
    shading::physicalNRow(sr, m, phis.data(), int(phis.size()), row.data());
    for (std::uint32_t i = 0; i < n0.width; ++i) {
      float* a = n0.texel(i, j);
      float* b = n1.texel(i, j);
      glm::dvec3 trt = row[i].trt + row[i].res;
      for (int c = 0; c < 3; ++c) {
        a[c] = shading::quantiseTexel(row[i].tt[c], n0.format);
        b[c] = shading::quantiseTexel(trt[c], n1.format);
      }
      a[3] = shading::quantiseTexel(row[i].r, n0.format);
    }
  }
}
}  // namespace

MarschnerLut buildPhysicalLut(const HairMaterial& material, LutFormat format) {
  material.validate();
  MarschnerLut lut;
  lut.mode = LutMode::Physical;
  lut.material = material;
  const std::uint32_t w = gpu::MARSCHNER_PHYSICAL_N_WIDTH, h = gpu::MARSCHNER_PHYSICAL_N_HEIGHT;
  LutTexture n0 = shading::makeLutTexture("N0", w, h, format);
  LutTexture n1 = shading::makeLutTexture("N1", w, h, format);
  n0.channelNames = {"N_TT.r", "N_TT.g", "N_TT.b", "N_R"};
  n1.channelNames = {"N_TRT.r + N_res.r", "N_TRT.g + N_res.g", "N_TRT.b + N_res.b", "unused"};
  n0.uAxis = n1.uAxis = "pseudo-angle P(phi/2): 0 at phi = 0, 1 at phi = pi, texel-centre mapped";
  n0.vAxis = n1.vAxis = "pseudo-angle P(|theta_r|): 0 at theta_r = 0, 1 at 90 deg, texel-centre mapped";
  buildN(material, n0, n1);
  lut.multipleScattering = multipleScatteringTables(material, int(gpu::MARSCHNER_SPREAD_ENTRIES));
  lut.textures = {buildM(material, lut.multipleScattering, format), std::move(n0), std::move(n1)};
  lut.parameterisation =
      "physical (d'Eon 2011 M, Chiang 2016 A_p and residual): P(a) = sin(a)/sqrt2 for a <= pi/4, "
      "1 - cos(a)/sqrt2 above, from sines with square roots only; S = (M_R N_R + M_TT N_TT + "
      "M_TRT (N_TRT + N_res)) / cos theta_i.";
  return lut;
}
}  // namespace hp
