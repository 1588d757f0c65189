#pragma once
// Contract: the whole-frame benchmark behind `hairpipe bench`: a scene (the default head's, or a scene file or
// model's) at one strand count,
// resolution and raster path, every frame recorded as `hairpipe render` records it (simulate,
// tessellate, interpolate, bounds, opacity, head, hair raster/shade, composite, tonemap) plus a
// vkCmdCopyBuffer reference in the same submission; one warm-up frame, then `frames` timed frames; then
// the copy alone in submissions of its own until stable (the bandwidth yardstick). Per pass: GPU-timestamp
// median/min/max and, for compute passes, the compulsory bytes moved; per frame the host wall time and the
// growth of the resident set (a driver that compiles per frame shows in both). The timestamps resolve the
// frame's passes when they time the copy alone (at least half of what its submission takes beyond an empty
// submission's wall time) and the copy inside the frame within 2x of alone; otherwise no bandwidth is
// derived and `unresolvedBecause` says why.
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "engine/core/hair/scene.h"
#include "compute/raster/frame_block.h"
#include "compute/raster/strand_raster_pass.h"
#include "compute/shadows/opacity_settings.h"
#include "engine/core/shading/lut.h"
#include "engine/vk/context.h"
#include "samples/tools/copy_reference.h"

namespace hp::cli {
struct FrameCase {
  // What is drawn, from prepareBenchModel: the scene (its camera framed, its size and density this case's) and the
  // asset built from it. Both not null; cases of one strand count share them.
  std::shared_ptr<const Scene> scene;
  std::shared_ptr<const HairAsset> asset;
  bool ownStrands = false;  // one render strand on every guide (a model's own strands) instead of `strands`
  std::uint32_t strands = 20000;  // render strands in total (DensityOptions::Total)
  std::uint32_t width = 640, height = 480;
  RasterMode raster = RasterMode::Compute;
  std::uint32_t msaa = 4;  // the head's samples (both paths) and the graphics path's hair samples
  std::uint32_t frames = 3;
  render::OpacityRaster opacityRaster = render::OpacityRaster::Auto;  // how strands reach the opacity maps
  bool skinBounce = true;  // compute only: LookSettings::skinBounce
  render::Scattering scattering = render::LookSettings{}.scattering;  // both paths
  LutMode lutMode = LutMode::Physical;  // the fibre model's device form (dual needs physical)
  float lodFraction = 1.0f;  // the strands drawn (a level of detail forced at every distance), widened
  std::uint32_t lights = 1;  // shadowed directional lights, [1, 4] (benchLights: the sun, then a rim, fill, top)
  std::uint32_t bounceSamples = gpu::RENDER_BOUNCE_STRAND_SAMPLES;  // StrandOptions::bounceSamples
  compute::FineWalk fineWalk = compute::FineWalk::Auto;  // compute only: RasterSettings::fineWalk
  bool groom = true;  // the scene's groom at interpolation (recommendedGroom), or none (the plain blend)
  bool skinIndirect = true;  // both paths: LookSettings::skinIndirect (the head's indirect light)
  std::uint32_t shadowStrands = render::OpacitySettings{}.shadowStrands;  // OpacitySettings::shadowStrands
  float shadingSpacing = compute::RasterSettings{}.shadingSpacing;  // compute only: RasterSettings::shadingSpacing
  bool growLists = false;  // compute only: RasterSettings::growLists
  HairMaterial material;  // the fibres (the scenes' by default; bench's material options)
};

struct PassTiming {
  double medianMs = 0, minMs = 0, maxMs = 0;
  double bytes = 0;  // compulsory traffic per frame (compute passes), 0 when not counted
};

struct FrameResult {
  FrameCase c;
  std::map<std::string, PassTiming> passes;  // "frame" is the whole frame; "copy" the reference
  std::uint64_t rasterEntries = 0, rasterOverflow = 0;
  std::uint64_t shadedVertices = 0;  // compute path: the vertices the shade pass shaded in the last frame
  compute::FineWalk fineWalkRun = compute::FineWalk::Auto;  // compute path: the fine walk taken (Auto resolved)
  render::OpacityRaster opacityRaster = render::OpacityRaster::Graphics;  // the path taken (Auto resolved)
  double opacityBufferBytes = 0;  // compute path: the bins in their form in effect, and deep maps' first hair
  double copyBytes = 0;
  vk::CopyTiming copyAlone;             // the yardstick: the copy in submissions of its own
  bool timestampsResolvePasses = false;
  std::string unresolvedBecause;         // empty when they do
  double hostMs = 0;          // median wall time of a frame's submit-and-wait (driver compiles included)
  double residentMiB = 0;     // the process's resident memory after the last frame
  double rasterTargetMiB = 0;  // compute path: the device memory its raster target holds (0 for graphics)
  double residentGrowthMiB = 0;  // per timed frame over the second half of the timed frames
};

// The scene and asset of every case at one strand count (host only, before any device is touched): the
// scene at width x height with its density set (`ownStrands`: the model's own strands, else `strands` in
// total), the asset built as `render` builds it and the camera framed as `render` frames it (frameCamera:
// a model without a scene; refused when no hair is in view). Sets c.scene and c.asset.
void prepareBenchModel(FrameCase& c, const Scene& base);

FrameResult benchFrame(const vk::Context& ctx, const FrameCase& c);
}  // namespace hp::cli
