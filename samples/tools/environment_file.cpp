#include "samples/tools/environment_file.h"

#include <algorithm>
#include <cctype>
#include <limits>
#include <string>

#include "engine/core/error.h"
#include "engine/core/hair/input_file.h"
#include "samples/tools/linear_image.h"
#include "samples/tools/stb_image_hdr.h"

namespace hp {
namespace {
constexpr std::uint64_t kMaxTexels = 8192ull * 4096ull;
constexpr std::uint64_t kMaxEnvironmentFileBytes = 1ull << 30;

std::string lowerExtension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

EnvironmentMap fromRgb(std::uint32_t width, std::uint32_t height, const float* rgb, const std::string& name) {
  if (std::uint64_t(width) * height > kMaxTexels)
    throw Error(name + ": an environment of " + std::to_string(width) + "x" + std::to_string(height) +
                " texels is larger than 8192x4096");
  EnvironmentMap map;
  map.width = width;
  map.height = height;
  map.texels.resize(std::size_t(width) * height);
  for (std::size_t i = 0; i < map.texels.size(); ++i) map.texels[i] = {rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2]};
  try {
    map.validate();
  } catch (const Error& e) {
    throw Error(name + ": " + e.what());
  }
  return map;
}

EnvironmentMap readHdr(const std::filesystem::path& path) {
  const std::vector<std::byte> bytes = readInputBytes(path, kMaxEnvironmentFileBytes);
  const std::string name = path.string();
  if (bytes.size() > std::size_t(std::numeric_limits<int>::max())) throw Error(name + ": file too large");
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  int w = 0, h = 0, channels = 0;
  if (!stb::hdrInfo(data, int(bytes.size()), &w, &h, &channels))
    throw Error(name + ": not a Radiance .hdr image (" + stb::failureReason() + ")");
  if (w < 1 || h < 1 || std::uint64_t(w) * std::uint64_t(h) > kMaxTexels)
    throw Error(name + ": an environment of " + std::to_string(w) + "x" + std::to_string(h) +
                " texels is outside 1x1..8192x4096");
  const stb::FloatImage image = stb::loadHdr(data, int(bytes.size()));
  if (!image.pixels) throw Error(name + ": cannot decode the .hdr image (" + stb::failureReason() + ")");
  return fromRgb(std::uint32_t(image.width), std::uint32_t(image.height), image.pixels.get(), name);
}

EnvironmentMap readPfmEnvironment(const std::filesystem::path& path) {
  const LinearImage image = readPfm(path);
  if (image.channels != 3) throw Error(path.string() + ": an environment .pfm must have 3 channels (PF)");
  return fromRgb(image.width, image.height, image.values.data(), path.string());
}
}  // namespace

EnvironmentMap readEnvironmentFile(const std::filesystem::path& path) {
  const std::string ext = lowerExtension(path);
  if (ext == ".hdr") return readHdr(path);
  if (ext == ".pfm") return readPfmEnvironment(path);
  throw Error(path.string() + ": an environment must be a Radiance .hdr or a .pfm image (OpenEXR is not read)");
}
}  // namespace hp
