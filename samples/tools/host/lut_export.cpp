#include "samples/tools/host/lut_export.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

namespace hp {
namespace {
void appendFloatLE(std::vector<std::byte>& out, float v) {
  std::uint32_t bits;
  std::memcpy(&bits, &v, 4);
  for (int b = 0; b < 4; ++b) out.push_back(std::byte((bits >> (8 * b)) & 0xffu));
}

std::vector<float> gather(const LutTexture& t, LutChannels which) {
  int first = which == LutChannels::Rgb ? 0 : 3, count = which == LutChannels::Rgb ? 3 : 1;
  std::vector<float> out;
  out.reserve(std::size_t(t.width) * t.height * count);
  for (std::size_t px = 0; px < std::size_t(t.width) * t.height; ++px)
    for (int c = 0; c < count; ++c) out.push_back(t.data[px * t.channels + first + c]);
  return out;
}
}  // namespace

std::vector<std::byte> encodePfm(std::uint32_t width, std::uint32_t height, int channels, const float* rowMajor) {
  std::string header = std::string(channels == 3 ? "PF" : "Pf") + "\n" + std::to_string(width) + " " +
                       std::to_string(height) + "\n-1.0\n";
  std::vector<std::byte> out;
  out.reserve(header.size() + std::size_t(width) * height * channels * 4);
  for (char c : header) out.push_back(std::byte(c));
  // PFM stores the bottom row first; our row 0 is v = 0, shown at the bottom.
  for (std::uint32_t j = 0; j < height; ++j)
    for (std::uint32_t k = 0; k < width * std::uint32_t(channels); ++k)
      appendFloatLE(out, rowMajor[std::size_t(j) * width * channels + k]);
  return out;
}

std::vector<std::byte> lutTexturePfm(const LutTexture& t, LutChannels which) {
  std::vector<float> values = gather(t, which);
  return encodePfm(t.width, t.height, which == LutChannels::Rgb ? 3 : 1, values.data());
}

PreviewImage lutPreviewRgb8(const LutTexture& t, LutChannels which) {
  int count = which == LutChannels::Rgb ? 3 : 1;
  std::vector<float> v = gather(t, which);
  float maxV[3] = {0, 0, 0};
  for (std::size_t k = 0; k < v.size(); ++k) maxV[k % count] = std::max(maxV[k % count], v[k]);
  PreviewImage img;
  img.width = t.width;
  img.height = t.height == 1 ? 32 : t.height;
  img.rgb.resize(std::size_t(img.width) * img.height * 3);
  for (std::uint32_t y = 0; y < img.height; ++y) {
    std::uint32_t row = t.height == 1 ? 0 : t.height - 1 - y;  // top of the image = last row
    for (std::uint32_t x = 0; x < img.width; ++x)
      for (int c = 0; c < 3; ++c) {
        int src = count == 3 ? c : 0;
        float f = v[(std::size_t(row) * t.width + x) * count + src];
        float n = maxV[src] > 0 ? std::clamp(f / maxV[src], 0.0f, 1.0f) : 0.0f;
        img.rgb[(std::size_t(y) * img.width + x) * 3 + c] =
            static_cast<std::uint8_t>(std::lround(255.0f * std::pow(n, 1.0f / 2.2f)));
      }
  }
  return img;
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
                   {"betaN_rad", m.betaN},
                   {"tiltVariation_rad", m.tiltVariation},
                   {"roughnessVariation", m.roughnessVariation}};
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
