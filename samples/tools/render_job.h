#pragma once
// Contract: renders one still of a scene the way `hairpipe render` does: builds a HairSystem over the
// asset, lets the simulation settle for settleFrames (the head following `animation`), then records
// the last frame in full (simulate, tessellate, interpolate, head, hair, tonemap) with GPU timestamps
// per pass (bounds and opacity included when shadows are on) and reads the image back. Blocking; for tools and tests, not for a frame loop.
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "engine/core/hair/hair_file.h"
#include "engine/core/shading/environment_map.h"
#include "samples/tools/hair_system.h"
#include "samples/tools/frame_capture.h"
#include "samples/tools/opacity_capture.h"
#include "samples/tools/host/head_animation.h"
#include "engine/vk/profiler.h"

namespace hp {
struct RenderRequest {
  Scene scene;                      // camera, lights, render size, material, simulation, density
  std::uint32_t settleFrames = 90;  // simulated frames before the rendered one
  HeadAnimation animation = HeadAnimation::None;
  std::string characterClip;  // an animation clip of the asset's skinned character (character_clip.h): "" none
  LutMode lutMode = LutMode::Physical;
  bool lines = false;
  bool guidesOnly = false;
  std::uint32_t bounceSamples = gpu::RENDER_BOUNCE_STRAND_SAMPLES;  // compute::StrandOptions::bounceSamples
  bool bounceAtGuides = true;                                         // compute::StrandOptions::bounceAtGuides
  bool drawHead = true;  // false: hair only (no proxy head drawn, shadowing or bouncing light)
  hairpipe::LodSettings lod;
  float exposure = 1.0f;
  render::LookSettings look;
  // The environment light whose SH look.environment holds, kept whole for the frame export (the path-traced
  // reference renders it texel for texel); null: none (the uniform look.ambient alone).
  std::shared_ptr<const EnvironmentMap> environment;
  // The environment's bright regions as lights, drawn after the scene's in the real-time frame only (the
  // reference traces the map itself). frameLights gives both.
  std::vector<LightSpec> environmentLights;
  render::OpacitySettings opacity;
  compute::RasterSettings rasterSettings;  // the compute raster's tile budget (scene.render.raster picks the path)
  bool captureOpacity = false;      // read shadow slot 0's opacity maps and light framing back (RenderResult::opacity)
  bool captureStrands = false;      // read the rendered frame's render strands back (RenderResult::strands)
  bool captureFrame = false;        // read strands, camera, linear image, hair coverage back (RenderResult::frame)
  // Motion vectors (compute raster): the last settling step is recorded as a frame's update too, so the
  // rendered frame's hair motion is that of its own simulation step; captureFrame reads it back.
  bool motionVectors = false;
};

// The real-time frame's lights: the scene's, then the environment's.
std::vector<LightSpec> frameLights(const RenderRequest& request);

struct RenderResult {
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::vector<std::uint8_t> rgba;        // sRGB, rows top to bottom
  std::vector<vk::ScopeTime> passTimes;  // GPU ms of each pass of the rendered frame
  std::uint32_t guides = 0;
  std::uint32_t strands = 0;
  std::uint32_t verticesPerStrand = 0;
  RasterMode raster = RasterMode::Graphics;          // the path that drew the hair (Auto resolved)
  render::OpacityRaster opacityRaster = render::OpacityRaster::Graphics;  // the path into the opacity maps
  std::optional<compute::RasterStats> rasterStats;   // compute raster: tile-list entries and overflow
  std::optional<render::OpacityCapture> opacity;  // with captureOpacity, shadows on and a light casting them
  std::optional<HairFileData> strandDump;         // with captureStrands: Q points per render strand
  std::optional<FrameCapture> frame;              // with captureFrame
};

// `progress` (optional) is told the settling frames done.
RenderResult renderStill(const vk::Context& ctx, const HairAsset& asset, const RenderRequest& request,
                         const std::function<void(std::uint32_t settled)>& progress = {});

// An animation: request.settleFrames simulated first, then `frames` frames each simulated and rendered
// in full (one simulation step apart, scene.simulation.dt). After each, `onFrame(index from 1, image)`;
// returning false stops the sequence there (Ctrl-C). Returns the frames rendered. The captures of the
// request are not made.
std::uint32_t renderSequence(const vk::Context& ctx, const HairAsset& asset, const RenderRequest& request,
                             std::uint32_t frames,
                             const std::function<bool(std::uint32_t frame, const RenderResult& image)>& onFrame);

// The HairSystem settings a render request implies for targets of `formats` (the viewer's too): a shadow
// slot for each of the scene's lights that casts shadows, up to the Renderer's limit (shadowSlotsFor).
HairSystemSettings systemSettings(const RenderRequest& request, const hairpipe::AttachmentFormats& formats);
// Throws hp::Error for a request renderStill would refuse (frame counts, exposure, lights).
void validateRequest(const RenderRequest& request);
// Throws hp::Error "<name> must be in (0, 1e6], got E" for an exposure the tonemap cannot take (render, view).
void validateExposure(float exposure, const std::string& name);
}  // namespace hp
