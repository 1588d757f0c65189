#pragma once
// Contract: reads an environment light from an equirectangular image file (the layout of
// engine/core/shading/environment_map.h: row 0 straight up, the middle column along +z): Radiance RGBE
// `.hdr` (through stb_image, images only of this kind compiled in) or `.pfm` (3 channels). Sizes are checked
// from the header before any pixel is decoded (at most 8192 x 4096 texels), then every texel (finite, not
// negative). Any problem is an hp::Error naming the file; nothing is half-read.
#include <filesystem>

#include "engine/core/shading/environment_map.h"

namespace hp {
EnvironmentMap readEnvironmentFile(const std::filesystem::path& path);
}  // namespace hp
