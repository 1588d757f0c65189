#pragma once
// Test assets: the default head with only every `stride`-th guide. The same hair, distance grid and
// particles per guide, fewer strands (fast on lavapipe), plus a sphere inside the cranium so the
// sphere colliders are exercised too.
#include <cstdint>

#include "engine/core/hair/hair_asset.h"

namespace hp::test {
HairAsset thinnedDefaultHead(std::uint32_t stride);
}  // namespace hp::test
