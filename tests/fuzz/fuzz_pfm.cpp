// PFM images (compare's and reference's input). Properties of an accepted image: a size inside the limit,
// 1 or 3 channels, exactly width x height x channels values; written back and read again it is bit-exact
// (the reader keeps every float, non-finite ones included: compare refuses those by name).
#include <cstdint>
#include <cstring>
#include <span>

#include "engine/core/error.h"
#include "samples/tools/linear_image.h"
#include "tests/fuzz/fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::byte> bytes(reinterpret_cast<const std::byte*>(data), size);
  hp::LinearImage image;
  try {
    image = hp::parsePfm(bytes, "fuzz.pfm");
  } catch (const hp::Error&) {
    return 0;
  }
  HP_FUZZ_REQUIRE(image.width >= 1 && image.width <= 16384 && image.height >= 1 && image.height <= 16384);
  HP_FUZZ_REQUIRE(image.channels == 1 || image.channels == 3);
  HP_FUZZ_REQUIRE(image.values.size() == std::size_t(image.width) * image.height * image.channels);
  const hp::LinearImage again = hp::parsePfm(hp::pfmBytes(image), "fuzz.pfm (written back)");
  HP_FUZZ_REQUIRE(again.width == image.width && again.height == image.height && again.channels == image.channels);
  HP_FUZZ_REQUIRE(std::memcmp(again.values.data(), image.values.data(), image.values.size() * sizeof(float)) == 0);
  return 0;
}
