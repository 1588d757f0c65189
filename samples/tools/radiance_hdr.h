#pragma once
// Contract: decodes a Radiance RGBE picture (`.hdr`) from memory into linear RGB floats, rows top first:
// the header ("#?RADIANCE" or "#?RGBE", FORMAT=32-bit_rle_rgbe; other variables ignored), the standard
// orientation line "-Y H +X W" only, then per scanline either the adaptive run-length form (2, 2, W) or flat
// RGBE pixels. Written here rather than taken from Debian's stb_image (2.27), whose decoder loops forever on
// a truncated run-length scanline. Every count is checked against the row and the bytes left; sizes are
// checked against `maxTexels` before anything is allocated. hp::Error naming `source` and the problem
// (truncated, a zero or overlong run, a bad header, an orientation it does not read).
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace hp {
struct RgbFloatImage {
  std::uint32_t width = 0, height = 0;
  std::vector<float> rgb;  // width x height x 3
};

RgbFloatImage decodeRadianceHdr(std::span<const std::byte> bytes, std::uint64_t maxTexels, const std::string& source);
}  // namespace hp
