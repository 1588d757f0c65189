#pragma once
// Contract: the opacity shadow map settings of a HairSystem (REFERENCES.md §4; engine/render/README.md
// "Opacity shadow maps"). Pure host data; validate() throws hp::Error naming the field.
#include <volk.h>

#include <cstdint>

namespace hp::render {
struct OpacitySettings {
  bool enabled = true;
  std::uint32_t resolution = 512;   // texels per side, [16, 4096] (docs/PERFORMANCE.md "Opacity maps")
  // footprint (default): a strand line adds width / texel size to each texel it crosses (its covered
  // fraction of the texel per texel of length), so alpha is the strands' projected area per texel
  // area and T = exp(-k alpha) is Beer-Lambert for randomly placed fibres, independent of the map's
  // resolution and the strand count. Otherwise a tuned constant strandOpacity per crossing.
  bool footprint = true;
  float strandOpacity = 0.04f;      // (0, 100]; constant mode only (the width comes from each instance's look)
  // The heads occlude through their own depth shadow map (ShadowMaps::headImage, head_shadow.glsl).
  // headOpacity > 0 also draws them into the opacity slices (the old path: its slices band the skin).
  float headOpacity = 0.0f;         // per head fragment, [0, 1e4]
  std::uint32_t headShadowResolution = 1024;  // head depth map texels per side, [16, 8192]
  float k = 1.0f;                   // T = exp(-k alpha), [0, 1e3]
  float biasSlices = 1.0f;          // lookups move this many slices toward the light, [0, 16]
  // RGBA32F: accurate additive sums (RGBA16F rounds each 0.04 by 17% past alpha 16 and drops it past
  // 128) and measured faster on lavapipe. RGBA16F is accepted for devices where bandwidth matters more.
  VkFormat format = VK_FORMAT_R32G32B32A32_SFLOAT;
  void validate() const;            // throws hp::Error naming the field
};
}  // namespace hp::render
