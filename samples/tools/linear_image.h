#pragma once
// Contract: a float image in memory (1 or 3 channels, rows top to bottom) and its Portable Float Map
// files: little-endian, scale -1, rows bottom to top on disk as the format requires. writePfm is
// atomic; readPfm validates the header and the byte count and throws hp::Error naming the file.
// displayRgba8 is the tonemap pass's display encoding on the host (exposure, shaders/shared/tonemap.h,
// sRGB transfer function), so a linear image becomes the PNG `hairpipe render` would write.
#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace hp {
struct LinearImage {
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::uint32_t channels = 3;  // 1 or 3
  std::vector<float> values;   // width * height * channels, top row first

  LinearImage() = default;
  LinearImage(std::uint32_t w, std::uint32_t h, std::uint32_t c) : width(w), height(h), channels(c), values(std::size_t(w) * h * c, 0.0f) {}
  float& at(std::uint32_t x, std::uint32_t y, std::uint32_t c) { return values[(std::size_t(y) * width + x) * channels + c]; }
  float at(std::uint32_t x, std::uint32_t y, std::uint32_t c) const { return values[(std::size_t(y) * width + x) * channels + c]; }
};

void writePfm(const std::filesystem::path& path, const LinearImage& image);
LinearImage readPfm(const std::filesystem::path& path);
// The same in memory: the file's bytes, and a PFM's bytes parsed (`source` names it in messages).
std::vector<std::byte> pfmBytes(const LinearImage& image);
LinearImage parsePfm(std::span<const std::byte> bytes, const std::string& source);

std::uint8_t srgbEncode8(float display);  // display value in [0, 1] -> sRGB byte, rounded
// RGBA8 (alpha 255), rows top to bottom; `image` must have 3 channels.
std::vector<std::uint8_t> displayRgba8(const LinearImage& image, float exposure);
}  // namespace hp
