#pragma once
// Contract: CPU construction of the Marschner lookup textures (docs/THEORY.md §3.7, docs/SHADING.md).
//  - LutMode::Paper: the paper's two RGBA8 128x128 textures (M over (sin theta_i, sin theta_r) with
//    cos theta_d in alpha; N over (cos phi, cos theta_d) with N_R in alpha and N_TT + N_TRT in rgb),
//    each channel rescaled into [0, 1] by its own factor (LutTexture::scale undoes it).
//  - LutMode::Float: RGBA16F (or RGBA32F on request) M (1D) and N0/N1 (2D) over the pseudo-angle
//    parameterisation of shaders/shared/marschner.h; separate lobes; scale = 1.
//  - LutMode::Direct: no textures.
//  - LutMode::Physical: the energy-conserving model (docs/THEORY.md §4), RGBA16F M (2D over theta_i,
//    theta_r) and N0/N1 (over phi, theta_r); scale = 1. The other three modes are the paper's model.
// Texel data are floats already quantised to the GPU format (RGBA8: k/255), row-major, 4 channels,
// row 0 at v = 0; texel (i, j) sits at texture coordinate ((i + 0.5)/width, (j + 0.5)/height).

#include <array>
#include <string>
#include <vector>

#include "engine/core/shading/material.h"
#include "engine/core/shading/multiple_scattering.h"

namespace hp {
enum class LutMode { Direct, Paper, Float, Physical };
enum class LutFormat { RGBA8Unorm, RGBA16F, RGBA32F };

const char* lutModeName(LutMode mode);
LutMode parseLutMode(const std::string& name);  // "direct" | "paper" | "float" | "physical", else hp::Error
const char* lutFormatName(LutFormat format);

struct LutTexture {
  std::string name;                 // "M", "N", "N0", "N1"
  std::uint32_t width = 0, height = 0;
  std::uint32_t channels = 4;
  LutFormat format = LutFormat::RGBA32F;
  std::array<float, 4> scale{1, 1, 1, 1};  // physical = sampled * scale, per channel
  std::array<std::string, 4> channelNames;
  std::string uAxis, vAxis;         // what the texture coordinates mean
  std::vector<float> data;          // width * height * channels

  float* texel(std::uint32_t i, std::uint32_t j) { return &data[(std::size_t(j) * width + i) * channels]; }
  const float* texel(std::uint32_t i, std::uint32_t j) const {
    return &data[(std::size_t(j) * width + i) * channels];
  }
};

struct MarschnerLut {
  LutMode mode = LutMode::Direct;
  HairMaterial material;
  std::vector<LutTexture> textures;  // paper: {M, N}; float, physical: {M, N0, N1}; direct: {}
  std::string parameterisation;      // human-readable summary
  // Physical only (empty otherwise): the dual-scattering tables, built once for both of their users, the M
  // texture's back lobe and the GPU block (marschner_gpu.h).
  MultipleScatteringTables multipleScattering;
};

struct LutBuildOptions {
  LutFormat floatFormat = LutFormat::RGBA16F;    // float and physical modes
  LutFormat paperFormat = LutFormat::RGBA8Unorm;  // RGBA32F only to separate 8-bit error when measuring
};

MarschnerLut buildLut(LutMode mode, const HairMaterial& material, const LutBuildOptions& options = {});
MarschnerLut buildPaperLut(const HairMaterial& material, LutFormat format = LutFormat::RGBA8Unorm);
MarschnerLut buildFloatLut(const HairMaterial& material, LutFormat format);
MarschnerLut buildPhysicalLut(const HairMaterial& material, LutFormat format);

}  // namespace hp

// The double-precision inverse of the `float`-mode LUT parameterisation of
// shaders/shared/marschner.h, used to place texel centres. pseudoAngle(a) is the forward map
// (a in [0, pi/2] -> [0, 1]); pseudoAngleInverse(x) its inverse; texelCentre(i, n) the value of
// x at texel i of an n-texel axis under marschnerTexelCentreCoord (i / (n - 1)).
namespace hp::shading {
double pseudoAngle(double a);
double pseudoAngleInverse(double x);
inline double texelCentre(unsigned i, unsigned n) { return double(i) / double(n - 1); }
}  // namespace hp::shading
