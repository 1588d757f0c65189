// TressFX .tfx decoding and import. Properties of an accepted file: counts in range and agreeing with
// the arrays (vertices per strand in 2..64, each optional array empty or of its full length), every
// value finite, inverse masses and thicknesses not negative, decode(encode(d)) == d bit for bit, and
// the import of its strands to guides (resampling, root triangulation, fitted collider) either refuses
// with hp::Error or yields finite guides and valid triangle indices.
#include <cstdint>
#include <cstring>
#include <span>

#include "engine/core/error.h"
#include "engine/core/hair/tfx_file.h"
#include "tests/fuzz/fuzz_check.h"
#include "tests/fuzz/fuzz_import.h"

namespace {
template <typename T>
bool sameBits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

template <typename T>
bool emptyOr(const std::vector<T>& values, std::uint64_t count) {
  return values.empty() || values.size() == count;
}

void checkAccepted(const hp::TfxData& d) {
  HP_FUZZ_REQUIRE(d.strandCount >= 1);
  HP_FUZZ_REQUIRE(d.verticesPerStrand >= 2 && d.verticesPerStrand <= 64);
  const std::uint64_t vertices = std::uint64_t(d.strandCount) * d.verticesPerStrand;
  HP_FUZZ_REQUIRE(d.positions.size() == vertices);
  HP_FUZZ_REQUIRE(emptyOr(d.strandUVs, d.strandCount) && emptyOr(d.strandThickness, d.strandCount));
  HP_FUZZ_REQUIRE(emptyOr(d.vertexUVs, vertices) && emptyOr(d.vertexColors, vertices));
  HP_FUZZ_REQUIRE(std::isfinite(d.version));
  for (const auto& p : d.positions) HP_FUZZ_REQUIRE(hp::fuzz::finite(glm::vec3(p)) && std::isfinite(p.w) && p.w >= 0.0f);
  for (const auto& uv : d.strandUVs) HP_FUZZ_REQUIRE(std::isfinite(uv.x) && std::isfinite(uv.y));
  for (const auto& uv : d.vertexUVs) HP_FUZZ_REQUIRE(std::isfinite(uv.x) && std::isfinite(uv.y));
  for (const auto& c : d.vertexColors) HP_FUZZ_REQUIRE(hp::fuzz::finite(glm::vec3(c)) && std::isfinite(c.w));
  for (float t : d.strandThickness) HP_FUZZ_REQUIRE(std::isfinite(t) && t >= 0.0f);
  const hp::TfxData again = hp::decodeTfx(hp::encodeTfx(d), "again.tfx");
  HP_FUZZ_REQUIRE(again.strandCount == d.strandCount && again.verticesPerStrand == d.verticesPerStrand);
  HP_FUZZ_REQUIRE(sameBits(again.positions, d.positions) && sameBits(again.strandUVs, d.strandUVs) &&
                  sameBits(again.vertexUVs, d.vertexUVs) && sameBits(again.strandThickness, d.strandThickness) &&
                  sameBits(again.vertexColors, d.vertexColors));
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::byte> bytes(reinterpret_cast<const std::byte*>(data), size);
  hp::TfxData d;
  try {
    d = hp::decodeTfx(bytes, "fuzz.tfx");
  } catch (const hp::Error&) {
    return 0;
  }
  checkAccepted(d);
  if (d.positions.size() > 4096) return 0;  // import cost grows with the points; keep each run short
  hp::fuzz::checkImport(hp::tfxToHair(d), "fuzz.tfx");
  return 0;
}
