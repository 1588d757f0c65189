// Mode names, dispatch and the JSON description of a Marschner LUT.
#include "engine/shading/lut.h"

#include <nlohmann/json.hpp>

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

nlohmann::json describeLut(const MarschnerLut& lut) {
  const HairMaterial& m = lut.material;
  nlohmann::json j;
  j["mode"] = lutModeName(lut.mode);
  j["parameterisation"] = lut.parameterisation;
  j["sampling"] = "bilinear, clamp to edge, texel centres at (i + 0.5) / n, row 0 at v = 0";
  j["material"] = {{"eta", m.eta},
                   {"absorption", {m.absorption.r, m.absorption.g, m.absorption.b}},
                   {"alphaR_rad", m.alphaR},
                   {"betaR_rad", m.betaR},
                   {"kG", m.kG},
                   {"wc_rad", m.wc},
                   {"dEta", m.dEta},
                   {"dhM", m.dhM},
                   {"betaN_rad", m.betaN}};
  j["textures"] = nlohmann::json::array();
  for (const LutTexture& t : lut.textures) {
    j["textures"].push_back({{"name", t.name},
                             {"width", t.width},
                             {"height", t.height},
                             {"format", lutFormatName(t.format)},
                             {"channels", t.channelNames},
                             {"scale", t.scale},
                             {"u", t.uAxis},
                             {"v", t.vAxis}});
  }
  return j;
}
}  // namespace hp
