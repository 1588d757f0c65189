#include "tests/support/thinned_head.h"

#include "engine/core/hair/default_head.h"
#include "engine/core/hair/head_sdf.h"

namespace hp::test {
HairAsset thinnedDefaultHead(std::uint32_t stride) {
  static const HairAsset full = buildDefaultHeadAsset();
  HairAsset asset;
  asset.colliders = {SphereCollider{kCraniumCenter, 0.07f}};
  asset.sdf = full.sdf;
  asset.guides.particlesPerGuide = full.guides.particlesPerGuide;
  for (std::uint32_t g = 0; g < full.guides.guideCount(); g += stride)
    for (const auto& p : full.guides.guide(g)) asset.guides.positions.push_back(p);
  return asset;
}
}  // namespace hp::test
