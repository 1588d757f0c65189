// Mode names, dispatch and the JSON description of a Marschner LUT; the float mode's parameterisation.
#include "engine/core/shading/lut.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "engine/core/error.h"

namespace hp {
const char* lutModeName(LutMode mode) {
  switch (mode) {
    case LutMode::Direct: return "direct";
    case LutMode::Paper: return "paper";
    case LutMode::Float: return "float";
    case LutMode::Physical: return "physical";
  }
  return "?";
}

LutMode parseLutMode(const std::string& name) {
  for (LutMode m : {LutMode::Direct, LutMode::Paper, LutMode::Float, LutMode::Physical})
    if (name == lutModeName(m)) return m;
  throw Error("unknown LUT mode '" + name + "' (expected direct, paper, float or physical)");
}

const char* lutFormatName(LutFormat format) {
  switch (format) {
    case LutFormat::RGBA8Unorm: return "R8G8B8A8_UNORM";
    case LutFormat::RGBA16F: return "R16G16B16A16_SFLOAT";
    case LutFormat::RGBA32F: return "R32G32B32A32_SFLOAT";
  }
  return "?";
}

MarschnerLut buildLut(LutMode mode, const HairMaterial& material, const LutBuildOptions& options) {
  switch (mode) {
    case LutMode::Paper: return buildPaperLut(material, options.paperFormat);
    case LutMode::Float: return buildFloatLut(material, options.floatFormat);
    case LutMode::Physical: return buildPhysicalLut(material, options.floatFormat);
    case LutMode::Direct: break;
  }
  material.validate();
  MarschnerLut lut;
  lut.mode = LutMode::Direct;
  lut.material = material;
  lut.parameterisation = "direct: S evaluated analytically in the shader, no textures";
  return lut;
}

}  // namespace hp

namespace hp::shading {
double pseudoAngle(double a) {
  constexpr double r = 1.0 / std::numbers::sqrt2;
  return a <= std::numbers::pi / 4 ? std::sin(a) * r : 1.0 - std::cos(a) * r;
}

double pseudoAngleInverse(double x) {
  x = std::clamp(x, 0.0, 1.0);
  constexpr double s2 = std::numbers::sqrt2;
  return x <= 0.5 ? std::asin(std::min(1.0, x * s2)) : std::acos(std::min(1.0, (1.0 - x) * s2));
}
}  // namespace hp::shading
