#pragma once
// Contract: PNG encode/decode of 8-bit images through libpng. encodePng takes rows top to bottom with
// 3 (RGB) or 4 (RGBA) channels; writePng writes atomically (the file appears whole under its name or
// not at all). Everything throws hp::Error naming the file or the problem.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <span>
#include <vector>

namespace hp {
std::vector<std::byte> encodePng(std::uint32_t width, std::uint32_t height, std::uint32_t channels,
                                 std::span<const std::uint8_t> pixels);
void writePng(const std::filesystem::path& path, std::uint32_t width, std::uint32_t height, std::uint32_t channels,
              std::span<const std::uint8_t> pixels);

struct RgbaImage {
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::vector<std::uint8_t> pixels;  // RGBA, rows top to bottom
};
RgbaImage readPngRgba(const std::filesystem::path& path);
}  // namespace hp
