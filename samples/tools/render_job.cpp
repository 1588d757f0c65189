#include "samples/tools/render_job.h"

#include <cmath>

#include "samples/tools/strand_dump.h"

#include "samples/tools/simulation_driver.h"
#include "engine/core/error.h"
#include "engine/core/number_text.h"
#include "samples/tools/offscreen_renderer.h"
#include "engine/vk/context.h"
#include "engine/vk/submit.h"
#include "engine/vk/transfer.h"

namespace hp {
namespace {
// What every rendered frame of a job shares: targets, the hair, the scripted head and the timestamps.
struct RenderSession {
  RenderSession(const vk::Context& ctx, const HairAsset& asset, const RenderRequest& request)
      : request(request),
        raster(motionRaster(request, resolveRasterMode(request.scene.render.raster, ctx.properties().deviceType))),
        renderer(ctx, request.scene.render.width, request.scene.render.height, request.scene.render.msaa, raster),
        clip(request.characterClip.empty() ? CharacterClip{} : characterClip(asset, request.characterClip)),
        hair(ctx, asset, withClipScalp(systemSettings(resolved(request, raster), renderer.formats()), asset, clip)),
        driver(ctx, hair.simulation(), request.animation, assetHeadRadius(asset)),
        profiler(ctx, 64, "render frame") {
    renderer.attach(hair);
    if (clip.clip) driver.setCharacterClip(clip);
  }

  static HairSystemSettings withClipScalp(HairSystemSettings s, const HairAsset& asset, const CharacterClip& clip) {
    if (clip.clip) s.scalp = characterScalp(asset);
    return s;
  }

  static RasterMode motionRaster(const RenderRequest& r, RasterMode raster) {
    if (r.motionVectors && raster != RasterMode::Compute)
      throw Error("motion vectors come from the compute raster: the graphics raster writes none");
    return raster;
  }

  static RenderRequest resolved(RenderRequest r, RasterMode raster) {
    r.scene.render.raster = raster;
    return r;
  }

  DrawView view(const HeadMotion& motion) const {
    DrawView v;
    v.extent = renderer.extent();
    v.camera = orbitCamera(request.scene.camera, float(v.extent.width) / float(v.extent.height));
    v.lights = frameLights(request);
    v.lines = request.lines;
    v.headToWorld = motion.to;
    return v;
  }

  // The next settling step as a frame's update (no draw): the render strands it interpolates become the
  // previous positions of the frame after it.
  void primeMotion(const vk::Context& ctx) {
    const HeadMotion motion = driver.advance();
    vk::submitAndWait(ctx, [&](VkCommandBuffer cmd) { hair.recordUpdate(cmd, motion); }, "motion prime");
  }

  // One frame in full (simulate, tessellate, interpolate, shadows, head, hair, tonemap), waited for.
  RenderResult render(const vk::Context& ctx, const HeadMotion& motion) {
    const DrawView v = view(motion);
    vk::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
      profiler.reset(cmd);
      hair.recordUpdate(cmd, motion, &profiler);
      hair.recordPrepareDraw(cmd, v, &profiler);
      renderer.record(cmd, hair, v, request.exposure, &profiler);
    }, "render frame");
    RenderResult result;
    result.width = v.extent.width;
    result.height = v.extent.height;
    result.rgba = renderer.readDisplay();
    result.passTimes = profiler.results();
    result.guides = hair.simulation().guideCount();
    result.strands = hair.strands().layout().strandCount;
    result.verticesPerStrand = hair.strands().layout().verticesPerStrand;
    result.raster = hair.raster();
    result.opacityRaster = hair.shadows().raster();
    return result;
  }

  const RenderRequest& request;
  RasterMode raster;
  render::OffscreenRenderer renderer;
  CharacterClip clip;
  HairSystem hair;
  SimulationDriver driver;
  vk::GpuProfiler profiler;
};
}  // namespace

HairSystemSettings systemSettings(const RenderRequest& r, const hairpipe::AttachmentFormats& formats) {
  HairSystemSettings s;
  s.simulation = r.scene.simulation;
  s.material = r.scene.material;
  s.lutMode = r.lutMode;
  s.strands.guidesOnly = r.guidesOnly;
  s.strands.bounceSamples = r.bounceSamples;
  s.strands.bounceAtGuides = r.bounceAtGuides;
  s.drawHead = r.drawHead;
  s.lod = r.lod;
  s.groom = r.scene.groom;
  s.formats = formats;
  s.look = r.look;
  s.opacity = r.opacity;
  s.shadowedLights = shadowSlotsFor(frameLights(r));
  s.motionVectors = r.motionVectors;
  s.raster = r.scene.render.raster;
  s.rasterSettings = r.rasterSettings;
  return s;
}

void validateExposure(float exposure, const std::string& name) {
  // 1e6 is past any useful exposure and keeps radiance x exposure (at most 65504 x 1e6) far inside float's
  // range; 3e38 made every lit pixel infinite, which the tonemap turned black.
  if (!(exposure > 0.0f && exposure <= 1.0e6f)) throw Error(name + " must be in (0, 1e6], got " + numberText(exposure));
}

void validateRequest(const RenderRequest& r) {
  if (r.settleFrames > 100000) throw Error("settle frames must be at most 100000");
  validateExposure(r.exposure, "exposure");
  validateLights(frameLights(r));  // also catches a hand-built LightSpec that skipped the scene parser
}

std::vector<LightSpec> frameLights(const RenderRequest& request) {
  std::vector<LightSpec> lights = request.scene.lights;
  lights.insert(lights.end(), request.environmentLights.begin(), request.environmentLights.end());
  return lights;
}

namespace {
// The light in shadow slot 0, whose maps captureOpacity reads: the first that casts shadows.
const LightSpec* firstShadowedLight(const std::vector<LightSpec>& lights) {
  for (const LightSpec& l : lights)
    if (l.shadows) return &l;
  return nullptr;
}

// What --export-frame writes: the drawn strands, the camera and head placement, the linear image.
FrameCapture captureFrame(const vk::Context& ctx, const HairSystem& hair, const render::OffscreenRenderer& renderer,
                          const DrawView& view) {
  FrameCapture f;
  f.strands = compute::readRenderStrands(ctx, hair.strands(), vk::BufferUse::VertexRead);
  f.verticesPerStrand = hair.strands().layout().verticesPerStrand;
  f.headToWorld = view.headToWorld;
  f.camera = view.camera;
  f.linear = renderer.readLinear();
  if (hair.raster() == RasterMode::Compute) {
    f.hairAlpha = LinearImage(renderer.extent().width, renderer.extent().height, 1);
    f.hairAlpha.values = hair.rasterCoverage();
  }
  if (hair.settings().motionVectors) {
    f.motion = LinearImage(renderer.extent().width, renderer.extent().height, 3);
    const std::vector<glm::vec2> motion = hair.rasterMotion();
    for (std::size_t i = 0; i < motion.size(); ++i) {
      f.motion.values[3 * i] = motion[i].x;
      f.motion.values[3 * i + 1] = motion[i].y;
    }
  }
  return f;
}
}  // namespace

RenderResult renderStill(const vk::Context& ctx, const HairAsset& asset, const RenderRequest& request,
                         const std::function<void(std::uint32_t settled)>& progress) {
  validateRequest(request);
  RenderSession session(ctx, asset, request);
  const bool prime = request.motionVectors && request.settleFrames > 0;
  if (request.settleFrames > 0) session.driver.runFrames(request.settleFrames - (prime ? 1 : 0), progress);
  if (prime) session.primeMotion(ctx);
  const HeadMotion motion = session.driver.nextMotion();
  RenderResult result = session.render(ctx, motion);
  HairSystem& hair = session.hair;
  if (hair.raster() == RasterMode::Compute) result.rasterStats = hair.rasterStats();
  if (request.captureStrands)
    result.strandDump = compute::renderStrandsToHairData(ctx, hair.strands(), vk::BufferUse::VertexRead,
                                                         "hairpipe render: render strands of the drawn frame");
  if (request.captureFrame) result.frame = captureFrame(ctx, hair, session.renderer, session.view(motion));
  const std::vector<LightSpec> lights = frameLights(request);
  const LightSpec* shadowed = firstShadowedLight(lights);
  if (request.captureOpacity && request.opacity.enabled && shadowed)
    result.opacity = render::captureOpacity(ctx, hair.shadows().image(), hair.shadows().lightSpace(), hair.shadows().settings(),
                                            glm::normalize(shadowed->direction));
  return result;
}

std::uint32_t renderSequence(const vk::Context& ctx, const HairAsset& asset, const RenderRequest& request,
                             std::uint32_t frames,
                             const std::function<bool(std::uint32_t frame, const RenderResult& image)>& onFrame) {
  validateRequest(request);
  RenderSession session(ctx, asset, request);
  if (request.settleFrames > 0) session.driver.runFrames(request.settleFrames);
  for (std::uint32_t i = 1; i <= frames; ++i) {
    const RenderResult image = session.render(ctx, session.driver.advance());
    if (!onFrame(i, image)) return i;
  }
  return frames;
}
}  // namespace hp
