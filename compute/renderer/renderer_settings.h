#pragma once
// Contract: the parameters of hp::Renderer (per device and attachment formats), of each hp::HairInstance
// (per head) and of one view of a frame. Pure host data; validate() throws hp::Error naming the field,
// and the Renderer/instance calls that take them validate them there, so recording never throws for them.
#include "hairpipe_volk.h"

#include <cstdint>
#include <optional>
#include <vector>

#include "compute/strands/scalp_input.h"
#include "compute/strands/strand_buffers.h"
#include "compute/raster/strand_raster_pass.h"
#include "engine/core/hair/groom.h"
#include "engine/core/hair/scene.h"
#include "engine/core/hair/sim_params.h"
#include "hairpipe/settings.h"
#include "compute/raster/camera.h"
#include "compute/raster/frame_block.h"
#include "compute/shadows/opacity_settings.h"
#include "engine/core/shading/lut.h"
#include "engine/core/shading/material.h"

namespace hp {
inline constexpr std::uint32_t kMaxFramesInFlight = 8;
inline constexpr std::uint32_t kMaxViewsPerFrame = 16;
// The fewest of its strands a level of detail may draw (LodSettings.minFraction, bench --lod-fraction): the
// strands drawn are widened by 1 / fraction, and below a thousandth they would be widths of whole heads.
inline constexpr float kMinLodFraction = 0.001f;

struct RendererSettings {
  hairpipe::AttachmentFormats formats;  // the application's attachments the draws go into
  render::OpacitySettings opacity;    // the shared opacity shadow maps (per shadowed light)
  // How many of a frame's lights cast hair shadows, [1, OPACITY_MAX_LIGHTS]: each owns opacity maps
  // (resolution^2 x 5 layers of the format), a LightSpace and a layer of the heads' depth map.
  std::uint32_t shadowedLights = 1;
  // Motion vectors: every instance keeps its previous render positions (a copy per recordUpdate) and the
  // compute raster target writes the hair's screen motion (Renderer::motionImage).
  bool motionVectors = false;
  // hairpipe::RendererSettings::velocityOutput: the composite writes the hair's motion into one of the
  // application's other colour attachments.
  hairpipe::VelocityOutput velocityOutput;
  // hairpipe::RendererSettings::applicationOccluders: hair-only instances frame the heads' depth map around
  // their guides, so the application can draw its occluders into it (Renderer::occluderTargets).
  bool applicationOccluders = false;
  std::uint32_t framesInFlight = 2;   // [1, kMaxFramesInFlight]
  std::uint32_t maxViewsPerFrame = 4; // [1, kMaxViewsPerFrame]: draws of one frame with different cameras
  // How hair reaches the camera: Graphics (ribbons in recordDraw) or Compute (setRasterTarget,
  // recordRaster, recordComposite; recordDraw draws the heads only). Auto resolves per device type
  // (resolveRasterMode). Graphics by default: an embedding that only calls recordDraw keeps drawing hair.
  RasterMode raster = RasterMode::Graphics;
  compute::RasterSettings rasterSettings;
  std::vector<std::uint8_t> pipelineCache;  // an earlier run's pipeline cache data (vk::PipelineLibrary)
  void validate() const;
};

struct InstanceSettings {
  SimulationParams simulation;
  HairMaterial material;
  LutMode lutMode = LutMode::Physical;
  compute::StrandOptions strands;
  render::LookSettings look;
  ScalpInput scalp;  // where the roots come from: rigid head (default), skinned root frames, or bones
  bool drawHead = true;  // false: hair only (hairpipe/settings.h says what that leaves out)
  hairpipe::LodSettings lod;
  GroomSettings groom;  // clumps, curl and frizz added at interpolation (engine/core/hair/groom.h)
  void validate() const;
};

// hp::Error naming the field unless `v` is off (attachment -1) or names one of formats.otherColors that is not
// an unused, SRGB or integer format, with motion vectors on, finite scales and offsets and minCoverage in [0, 1).
void validateVelocityOutput(const hairpipe::VelocityOutput& v, const hairpipe::AttachmentFormats& formats,
                            bool motionVectors);
// hp::Error naming the field unless the distances are finite, 0 <= start < end, and minFraction in
// [kMinLodFraction, 1].
void validate(const hairpipe::LodSettings& lod);
// The fraction of the strands drawn at `distance` (1 when LOD is off; see hairpipe::LodSettings).
float lodFraction(const hairpipe::LodSettings& lod, float distance);
// The strands of an instance the opacity maps draw: the first `drawn` of them, the view's level of detail
// (lodFraction) capped at OpacitySettings::shadowStrands (0: no cap), and the fraction of all strands they
// stand for (each is widened by 1 / fraction).
struct ShadowSample {
  std::uint32_t drawn = 0;
  float fraction = 1.0f;
};
ShadowSample shadowSample(float lodFraction, std::uint32_t strands, std::uint32_t budget);
// The strands a fraction of `strands` draws: at least one.
std::uint32_t lodStrandCount(float fraction, std::uint32_t strands);
// The look a view at `fraction` draws with: the strands widened by 1 / fraction, so the hair keeps its
// coverage.
render::LookSettings lodLook(render::LookSettings look, float fraction);

// Auto -> the path measured faster on this device type (docs/PERFORMANCE.md "Compute rasterizer").
RasterMode resolveRasterMode(RasterMode mode, VkPhysicalDeviceType type);

// One camera of a frame. Several views of one frame (a mirror, split screen) reuse its update and
// shadows; each needs its own `index`, below RendererSettings::maxViewsPerFrame.
struct View {
  CameraMatrices camera;
  VkExtent2D extent{1, 1};
  bool lines = false;       // strands as 1-pixel lines instead of ribbons (debugging)
  std::uint32_t index = 0;  // which of the frame's views
  bool ribbons = true;      // false: heads only (the hair comes from the compute rasterizer)
  // Subpixel jitter in pixels (x right, y down), each in [-1, 1]: hairpipe offsets its projection by it
  // (heads and hair, both rasters); motion vectors leave it out.
  glm::vec2 jitter{0.0f};
  // The previous frame's unjittered proj * view, for motion vectors; none: the camera did not move.
  std::optional<glm::mat4> previousViewProj;
  // An application's view (the public API's): its projection is checked against the depth convention (the
  // tools' own views, some without a projection in shadow-only frames, are not).
  bool fromApplication = false;
  // maxViews and, for an application's view, the depth convention: a right-handed projection's depth falls
  // toward the eye (proj[2][2] < 0) forward and rises reversed (>= 0: 0 with the far plane at infinity); the
  // other way draws nothing. Throws hp::Error naming the problem.
  void validate(std::uint32_t maxViews, bool reversedDepth) const;
};
}  // namespace hp
