#pragma once
// Contract: file encodings of LUT textures (no I/O here; callers write the bytes atomically).
//  - encodePfm(): Portable Float Map, little-endian ("PF" 3 channels / "Pf" 1 channel, scale -1),
//    rows bottom-to-top as the format requires, so texture row 0 (v = 0) is the image's bottom row.
//    lutTexturePfm() exports channels 0-2 ("rgb") or channel 3 ("a") of a texture: the stored
//    (possibly rescaled) values; physical value = stored * scale, listed in the LUT JSON.
//  - lutPreviewRgb8(): an 8-bit RGB preview of channels 0-2 (or 3 as grey), each channel divided by
//    its maximum and gamma 1/2.2 for visibility; height-1 textures are repeated to 32 rows.
//    Rows top-to-bottom with v = 0 at the bottom, matching the PFM orientation.
#include <cstddef>
#include <cstdint>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "engine/core/shading/lut.h"

namespace hp {
enum class LutChannels { Rgb, Alpha };

std::vector<std::byte> encodePfm(std::uint32_t width, std::uint32_t height, int channels, const float* rowMajor);
std::vector<std::byte> lutTexturePfm(const LutTexture& texture, LutChannels which);

struct PreviewImage {
  std::uint32_t width = 0, height = 0;
  std::vector<std::uint8_t> rgb;  // width * height * 3, top row first
};
PreviewImage lutPreviewRgb8(const LutTexture& texture, LutChannels which);
// The LUT set as JSON: layout, parameterisation, scales, material (`hairpipe lut`'s description file).
nlohmann::json describeLut(const MarschnerLut& lut);
}  // namespace hp
