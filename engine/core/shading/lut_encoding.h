#pragma once
// Contract: a material's Marschner tables (lut.h) as bytes and back, every field, so that decoding what encoding
// wrote gives tables equal to the original bit for bit. The encoding is the host's own (byte_stream.h): for the
// disk cache of one build (lut_cache.h), not an exchange format. decodeLut throws hp::Error on bytes that are not
// a whole encoding (too short, trailing bytes, a texture whose data does not fill its size).
#include <cstddef>
#include <span>
#include <vector>

#include "engine/core/shading/lut.h"

namespace hp {
std::vector<std::byte> encodeLut(const MarschnerLut& lut);
MarschnerLut decodeLut(std::span<const std::byte> bytes);
}  // namespace hp
