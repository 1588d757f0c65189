#pragma once
// Contract: reads an environment light from an equirectangular image file (the layout of
// engine/core/shading/environment_map.h: row 0 straight up, the middle column along +z): Radiance RGBE
// `.hdr` (radiance_hdr.h) or `.pfm` (3 channels). Sizes are checked from the header before any pixel is
// decoded (at most kMaxEnvironmentTexels, 8192 x 4096), then every texel (EnvironmentMap::validate). Any
// problem, a truncated file included, is an hp::Error naming the file; nothing is half-read.
#include <filesystem>

#include "engine/core/shading/environment_map.h"

namespace hp {
EnvironmentMap readEnvironmentFile(const std::filesystem::path& path);  // by the extension: .hdr or .pfm
EnvironmentMap readHdrEnvironment(const std::filesystem::path& path);   // a Radiance .hdr, whatever its name
}  // namespace hp
