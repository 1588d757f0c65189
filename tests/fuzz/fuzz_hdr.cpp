// Radiance .hdr environments (render --environment). Properties of an accepted image: a size inside the
// texel limit given, exactly width x height x 3 values, every one finite and >= 0 (RGBE holds nothing else);
// and a header claiming a size the bytes cannot hold is refused before the image is made (the limit here is
// far above what a fuzz input holds, so an acceptance of a large image would show as one).
#include <cmath>
#include <cstdint>
#include <span>

#include "engine/core/error.h"
#include "samples/tools/radiance_hdr.h"
#include "tests/fuzz/fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::byte> bytes(reinterpret_cast<const std::byte*>(data), size);
  constexpr std::uint64_t kMaxTexels = 8192ull * 4096;
  hp::RgbFloatImage image;
  try {
    image = hp::decodeRadianceHdr(bytes, kMaxTexels, "fuzz.hdr");
  } catch (const hp::Error&) {
    return 0;
  }
  HP_FUZZ_REQUIRE(image.width >= 1 && image.height >= 1 && std::uint64_t(image.width) * image.height <= kMaxTexels);
  HP_FUZZ_REQUIRE(image.rgb.size() == std::size_t(image.width) * image.height * 3);
  // Each scanline takes at least 8 bytes per 127 texels of run-length data: an image the input cannot hold
  // was made from the header alone.
  HP_FUZZ_REQUIRE(std::uint64_t(image.width) * image.height <= std::uint64_t(size) * 127);
  for (const float v : image.rgb) HP_FUZZ_REQUIRE(std::isfinite(v) && v >= 0.0f);
  return 0;
}
