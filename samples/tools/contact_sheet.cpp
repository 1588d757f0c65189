#include "samples/tools/contact_sheet.h"

#include <algorithm>

#include "engine/core/error.h"

namespace hp {
namespace {
constexpr std::uint32_t kGutter = 2;
constexpr std::uint8_t kGutterRgba[4] = {12, 13, 15, 255};
}  // namespace

RgbaImage contactSheet(std::span<const RgbaImage> frames, std::uint32_t columns) {
  if (frames.empty()) throw Error("contact sheet: no frames");
  if (columns == 0) throw Error("contact sheet: columns must be at least 1");
  const std::uint32_t w = frames[0].width, h = frames[0].height;
  for (const auto& f : frames)
    if (f.width != w || f.height != h || f.pixels.size() != std::size_t(w) * h * 4)
      throw Error("contact sheet: frames differ in size");
  const std::uint32_t cols = std::min<std::uint32_t>(columns, std::uint32_t(frames.size()));
  const std::uint32_t rows = (std::uint32_t(frames.size()) + cols - 1) / cols;
  RgbaImage sheet;
  sheet.width = cols * w + (cols - 1) * kGutter;
  sheet.height = rows * h + (rows - 1) * kGutter;
  sheet.pixels.resize(std::size_t(sheet.width) * sheet.height * 4);
  for (std::size_t i = 0; i < sheet.pixels.size(); ++i) sheet.pixels[i] = kGutterRgba[i % 4];
  for (std::size_t i = 0; i < frames.size(); ++i) {
    const std::uint32_t x0 = std::uint32_t(i % cols) * (w + kGutter), y0 = std::uint32_t(i / cols) * (h + kGutter);
    for (std::uint32_t y = 0; y < h; ++y)
      std::copy_n(frames[i].pixels.begin() + std::ptrdiff_t(std::size_t(y) * w * 4), std::size_t(w) * 4,
                  sheet.pixels.begin() + std::ptrdiff_t((std::size_t(y0 + y) * sheet.width + x0) * 4));
  }
  return sheet;
}

std::vector<std::uint32_t> sheetFrames(std::uint32_t frames, std::uint32_t tiles) {
  std::vector<std::uint32_t> picked;
  if (frames == 0 || tiles == 0) return picked;
  const std::uint32_t n = std::min(frames, tiles);
  for (std::uint32_t i = 0; i < n; ++i)
    picked.push_back(n == 1 ? frames : 1 + std::uint32_t(std::uint64_t(i) * (frames - 1) / (n - 1)));
  return picked;
}
}  // namespace hp
