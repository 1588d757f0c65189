#include "samples/tools/linear_image.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <sstream>
#include <string_view>

#include "engine/core/error.h"
#include "engine/core/hair/atomic_write.h"
#include "engine/core/hair/input_file.h"
#include "samples/tools/host/lut_export.h"
#include "shaders/shared/tonemap.h"

namespace hp {
namespace {
constexpr std::uint32_t kMaxSide = 16384;

std::vector<float> flipRows(const LinearImage& image) {
  const std::size_t row = std::size_t(image.width) * image.channels;
  std::vector<float> out(image.values.size());
  for (std::uint32_t y = 0; y < image.height; ++y)
    std::memcpy(out.data() + (image.height - 1 - y) * row, image.values.data() + y * row, row * sizeof(float));
  return out;
}
}  // namespace

std::vector<std::byte> pfmBytes(const LinearImage& image) {
  if (image.channels != 1 && image.channels != 3) throw Error("writePfm: 1 or 3 channels, not " + std::to_string(image.channels));
  if (image.values.size() != std::size_t(image.width) * image.height * image.channels)
    throw Error("writePfm: the image's values do not match its size");
  const std::vector<float> bottomUp = flipRows(image);
  return encodePfm(image.width, image.height, int(image.channels), bottomUp.data());
}

void writePfm(const std::filesystem::path& path, const LinearImage& image) {
  writeFileAtomically(path, pfmBytes(image));
}

LinearImage readPfm(const std::filesystem::path& path) {
  return parsePfm(readInputBytes(path, kMaxImageFileBytes), path.string());
}

LinearImage parsePfm(std::span<const std::byte> bytes, const std::string& source) {
  const std::string_view text(reinterpret_cast<const char*>(bytes.data()), std::min<std::size_t>(bytes.size(), 128));
  std::istringstream header{std::string(text)};
  std::string magic;
  long long w = 0, h = 0;
  double scale = 0;
  header >> magic >> w >> h >> scale;
  if (!header || (magic != "PF" && magic != "Pf")) throw Error("'" + source + "' is not a PFM file (PF or Pf header)");
  if (w < 1 || h < 1 || w > kMaxSide || h > kMaxSide) throw Error("'" + source + "': PFM size must be in [1, 16384]");
  if (!(scale < 0)) throw Error("'" + source + "': only little-endian PFM (negative scale) is read");
  // The header ends with one whitespace character after the scale; the data must be exactly what the
  // header promises, checked before anything is allocated for it.
  const std::streamoff scaleEnd = header.tellg();
  const auto isSpace = [](std::byte b) { return b == std::byte{' '} || b == std::byte{'\n'} || b == std::byte{'\r'} || b == std::byte{'\t'}; };
  if (scaleEnd < 0 || std::size_t(scaleEnd) >= bytes.size() || !isSpace(bytes[std::size_t(scaleEnd)]))
    throw Error("'" + source + "': the PFM header must end with one whitespace character before the data");
  const std::size_t dataStart = std::size_t(scaleEnd) + 1;
  const std::uint32_t channels = magic == "PF" ? 3u : 1u;
  const std::size_t dataBytes = std::size_t(w) * std::size_t(h) * channels * sizeof(float);
  if (bytes.size() != dataStart + dataBytes)
    throw Error("'" + source + "': PFM data size does not match its header (" + std::to_string(w) + "x" +
                std::to_string(h) + "x" + std::to_string(channels) + " floats need " + std::to_string(dataBytes) +
                " bytes after the header, the file has " + std::to_string(bytes.size() - std::min(bytes.size(), dataStart)) + ")");
  LinearImage image(std::uint32_t(w), std::uint32_t(h), channels);
  std::memcpy(image.values.data(), bytes.data() + dataStart, image.values.size() * sizeof(float));
  image.values = flipRows(image);  // the file's rows are bottom to top
  return image;
}

std::uint8_t srgbEncode8(float display) {
  const float c = std::clamp(display, 0.0f, 1.0f);
  const float e = c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
  return std::uint8_t(std::lround(e * 255.0f));
}

std::vector<std::uint8_t> displayRgba8(const LinearImage& image, float exposure) {
  if (image.channels != 3) throw Error("displayRgba8: the image must have 3 channels");
  std::vector<std::uint8_t> out(std::size_t(image.width) * image.height * 4, 255);
  for (std::size_t i = 0; i < std::size_t(image.width) * image.height; ++i)
    for (int c = 0; c < 3; ++c) out[i * 4 + c] = srgbEncode8(gpu::tonemapFilmic(image.values[i * 3 + c] * exposure));
  return out;
}
}  // namespace hp
