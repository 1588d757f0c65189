#pragma once
// Shared by the .hair and .tfx fuzz targets: the import of accepted strands to guides (resampling, root
// triangulation, fitted collider) either refuses with hp::Error or yields one finite guide per strand
// and triangle indices in range. Bounded work per input: 64 render strands.
#include "engine/core/error.h"
#include "engine/core/hair/hair_import.h"
#include "tests/fuzz/fuzz_check.h"

namespace hp::fuzz {
inline void checkImport(const HairFileData& d, const char* source) {
  HairImportOptions options;
  options.density.totalStrands = 64;
  options.density.mode = DensityOptions::Mode::Total;
  HairAsset asset;
  try {
    asset = importHairAsset(d, options, source);
  } catch (const Error&) {
    return;
  }
  for (const auto& p : asset.guides.positions) HP_FUZZ_REQUIRE(finite(glm::vec3(p)));
  const std::size_t roots = asset.guides.guideCount();
  HP_FUZZ_REQUIRE(roots == d.strandCount);
  for (const auto& t : asset.topology.triangles) HP_FUZZ_REQUIRE(t.x < roots && t.y < roots && t.z < roots);
}
}  // namespace hp::fuzz
