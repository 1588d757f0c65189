#include "samples/tools/environment_file.h"

#include <algorithm>
#include <cctype>
#include <string>

#include "engine/core/error.h"
#include "engine/core/hair/input_file.h"
#include "samples/tools/linear_image.h"
#include "samples/tools/radiance_hdr.h"

namespace hp {
namespace {
constexpr std::uint64_t kMaxEnvironmentFileBytes = 1ull << 30;

std::string lowerExtension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext;
}

EnvironmentMap fromRgb(std::uint32_t width, std::uint32_t height, const float* rgb, const std::string& name) {
  EnvironmentMap map;
  map.width = width;
  map.height = height;
  if (std::uint64_t(width) * height > kMaxEnvironmentTexels)
    throw Error(name + ": an environment of " + std::to_string(width) + "x" + std::to_string(height) +
                " texels is larger than 8192x4096");
  map.texels.resize(std::size_t(width) * height);
  for (std::size_t i = 0; i < map.texels.size(); ++i) map.texels[i] = {rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2]};
  try {
    map.validate();
  } catch (const Error& e) {
    throw Error(name + ": " + e.what());
  }
  return map;
}

EnvironmentMap readPfmEnvironment(const std::filesystem::path& path) {
  const LinearImage image = readPfm(path);
  if (image.channels != 3) throw Error(path.string() + ": an environment .pfm must have 3 channels (PF)");
  return fromRgb(image.width, image.height, image.values.data(), path.string());
}
}  // namespace

EnvironmentMap readHdrEnvironment(const std::filesystem::path& path) {
  const std::vector<std::byte> bytes = readInputBytes(path, kMaxEnvironmentFileBytes);
  const RgbFloatImage image = decodeRadianceHdr(bytes, kMaxEnvironmentTexels, path.string());
  return fromRgb(image.width, image.height, image.rgb.data(), path.string());
}

EnvironmentMap readEnvironmentFile(const std::filesystem::path& path) {
  const std::string ext = lowerExtension(path);
  if (ext == ".hdr") return readHdrEnvironment(path);
  if (ext == ".pfm") return readPfmEnvironment(path);
  throw Error(path.string() + ": an environment must be a Radiance .hdr or a .pfm image (OpenEXR is not read)");
}
}  // namespace hp
