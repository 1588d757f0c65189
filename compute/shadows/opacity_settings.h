#pragma once
// Contract: the opacity shadow map settings of a Renderer (docs/THEORY.md §5; compute/shadows/README.md
// "Opacity shadow maps"). The struct and the raster enum are defined once, in the public API
// (hairpipe/settings.h); here are their parsing, validation (hp::Error naming the field) and the notes
// behind the fields:
// - raster: Compute splats each segment's fragments with one fixed-point atomic add into one slice bin
//   and resolves the bins (compute::OpacitySplatPass / OpacityResolvePass); Graphics draws them as lines
//   blended additively into all 16 slices. The same rasterization rule and opacities, so the maps agree up
//   to the fixed point's rounding; compute is 2-4x faster on lavapipe (docs/PERFORMANCE.md "Opacity
//   maps"). Its bins (resolution^2 x 64 bytes) must fit the device's maxStorageBufferRange (128 MiB on
//   lavapipe: up to 1448^2); Auto takes Compute where they fit and Graphics otherwise (ShadowMaps::raster()
//   says which); Compute past the limit is refused. Fixed for a Renderer, like resolution and format.
// - footprint (default): a strand line adds width / texel size to each texel it crosses (its covered
//   fraction of the texel per texel of length), so alpha is the strands' projected area per texel area and
//   T = exp(-k alpha) is Beer-Lambert for randomly placed fibres, independent of the map's resolution and
//   the strand count. Otherwise a tuned constant strandOpacity per crossing (the width comes from each
//   instance's look).
// - headOpacity: the heads occlude through their own depth shadow map (ShadowMaps::headImage,
//   head_shadow.glsl); headOpacity > 0 also draws them into the opacity slices (the old path: its slices
//   band the skin). It does not apply to deep maps.
// - deepBiasSlices 0.25 with dual scattering: docs/SHADING.md "Local back-scattering".
// - format RGBA32F: accurate additive sums (RGBA16F rounds each 0.04 by 17% past alpha 16 and drops it
//   past 128) and measured faster on lavapipe; RGBA16F is accepted where bandwidth matters more.
// - deep: deep opacity maps (Yuksel & Keyser 2008) on the compute path (the graphics path draws global
//   slices: ShadowMaps::settings() says which are in effect): the slices start at each texel's first hair
//   and are OPACITY_DEEP_FACTOR times finer, following the hair's surface (docs/SHADING.md "Deep opacity
//   maps"). On by default with the skin's bounce (docs/SHADING.md "Skin bounce").
#include <string>

#include "hairpipe/settings.h"

namespace hp::render {
using OpacityRaster = hairpipe::OpacityRaster;
using OpacitySettings = hairpipe::OpacitySettings;

OpacityRaster parseOpacityRaster(const std::string& text);  // "auto", "compute", "graphics"; else hp::Error
const char* opacityRasterName(OpacityRaster raster);
void validate(const OpacitySettings& settings);              // throws hp::Error naming the field
// The bias of the slices in effect (deep or global).
inline float lookupBias(const OpacitySettings& s) { return s.deep ? s.deepBiasSlices : s.biasSlices; }
}  // namespace hp::render
