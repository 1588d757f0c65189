// .hair decoding and import. Properties of an accepted file: counts agree with the arrays, every value
// finite, the encoding round-trips byte for byte, and the import to guides (resampling, root
// triangulation, fitted collider) either refuses with hp::Error or yields finite guides and valid
// triangle indices.
#include <cstdint>
#include <span>

#include "engine/core/error.h"
#include "engine/core/hair/hair_file.h"
#include "tests/fuzz/fuzz_check.h"
#include "tests/fuzz/fuzz_import.h"

namespace {
void checkAccepted(const hp::HairFileData& d, std::span<const std::byte> bytes) {
  HP_FUZZ_REQUIRE(d.strandCount >= 1);
  HP_FUZZ_REQUIRE(d.strandOffsets().back() == d.pointCount());
  for (const auto& p : d.points) HP_FUZZ_REQUIRE(hp::fuzz::finite(p));
  const std::vector<std::byte> again = hp::encodeHair(d);
  HP_FUZZ_REQUIRE(again.size() == bytes.size() && std::equal(again.begin(), again.end(), bytes.begin()));
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::byte> bytes(reinterpret_cast<const std::byte*>(data), size);
  hp::HairFileData d;
  try {
    d = hp::decodeHair(bytes, "fuzz.hair");
  } catch (const hp::Error&) {
    return 0;
  }
  checkAccepted(d, bytes);
  if (d.pointCount() > 4096) return 0;  // import cost grows with the points; keep each run short
  hp::fuzz::checkImport(d, "fuzz.hair");
  return 0;
}
