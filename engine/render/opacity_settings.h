#pragma once
// Contract: the opacity shadow map settings of a HairSystem (docs/THEORY.md §5; engine/render/README.md
// "Opacity shadow maps"). Pure host data; validate() throws hp::Error naming the field.
#include "hairpipe_volk.h"

#include <cstdint>
#include <string>

namespace hp::render {
// How strands reach the opacity maps: Compute splats each segment's fragments with one fixed-point atomic
// add into one slice bin and resolves the bins (compute::OpacitySplatPass / OpacityResolvePass); Graphics
// draws them as lines blended additively into all 16 slices. The same rasterization rule and opacities,
// so the maps agree up to the fixed point's rounding; compute is 2-4x faster on lavapipe (docs/
// PERFORMANCE.md "Opacity maps"). Its bins (resolution^2 x 64 bytes) must fit the device's
// maxStorageBufferRange (128 MiB on lavapipe: up to 1448^2); Auto (the default) takes Compute where they
// fit and Graphics otherwise (ShadowMaps::raster() says which); Compute past the limit is refused.
enum class OpacityRaster { Auto, Compute, Graphics };
OpacityRaster parseOpacityRaster(const std::string& text);  // "auto", "compute", "graphics"; else hp::Error
const char* opacityRasterName(OpacityRaster raster);

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
  float biasSlices = 1.0f;          // global slices: lookups move this many slices toward the light, [0, 16]
  // Deep maps: the same in deep slices, [0, 16]. 0.25 with dual scattering: docs/SHADING.md "Local
  // back-scattering" (0.5 before, the choice of "Skin bounce").
  float deepBiasSlices = 0.25f;
  // RGBA32F: accurate additive sums (RGBA16F rounds each 0.04 by 17% past alpha 16 and drops it past
  // 128) and measured faster on lavapipe. RGBA16F is accepted for devices where bandwidth matters more.
  VkFormat format = VK_FORMAT_R32G32B32A32_SFLOAT;
  OpacityRaster raster = OpacityRaster::Auto;  // fixed for a Renderer, like resolution and format
  // Deep opacity maps (Yuksel & Keyser 2008), on the compute path (the graphics path draws global slices:
  // ShadowMaps::settings() says which are in effect): the slices start at each texel's first hair and
  // are OPACITY_DEEP_FACTOR times finer, following the hair's surface instead of cutting the whole head
  // into 16 (docs/SHADING.md "Deep opacity maps"); deepBiasSlices is their bias. On by default since the
  // skin's bounce (LookSettings::skinBounce) supplies the light the reference's multiple scattering adds:
  // together they are closer to the reference in every view measured (docs/SHADING.md "Skin bounce").
  // headOpacity (the head in the slices, drawn at global slice coordinates) does not apply to deep maps.
  bool deep = true;
  float lookupBias() const { return deep ? deepBiasSlices : biasSlices; }  // the bias of the slices in effect
  void validate() const;            // throws hp::Error naming the field
};
}  // namespace hp::render
