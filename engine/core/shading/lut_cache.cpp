#include "engine/core/shading/lut_cache.h"

#include "engine/core/recent_cache.h"

namespace hp {
namespace {
struct LutKey {
  LutMode mode;
  HairMaterial material;
  LutFormat floatFormat, paperFormat;
  bool operator==(const LutKey&) const = default;
};

// A physical model's tables are ~2 MiB; four materials cover a tool comparing looks or a viewer's edits. Never
// destroyed: a material's build on a detached worker (compute/renderer/lut_build.h) may outlive main.
RecentCache<LutKey, MarschnerLut, 4>& luts() {
  static auto& cache = *new RecentCache<LutKey, MarschnerLut, 4>;
  return cache;
}
}  // namespace

std::shared_ptr<const MarschnerLut> sharedLut(LutMode mode, const HairMaterial& material,
                                              const LutBuildOptions& options) {
  return luts().get(LutKey{mode, material, options.floatFormat, options.paperFormat},
                  [&] { return buildLut(mode, material, options); });
}
}  // namespace hp
