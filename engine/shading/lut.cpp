// Mode names, dispatch and the JSON description of a Marschner LUT.
#include "engine/shading/lut.h"


#include "engine/error.h"

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
