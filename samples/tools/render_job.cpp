#include "samples/tools/render_job.h"

#include "samples/tools/strand_dump.h"

#include "samples/tools/simulation_driver.h"
#include "engine/error.h"
#include "samples/tools/offscreen_renderer.h"
#include "engine/vk/context.h"
#include "engine/vk/submit.h"
#include "engine/vk/transfer.h"

namespace hp {
namespace {
HairSystemSettings systemSettings(const RenderRequest& r, const render::AttachmentFormats& formats) {
  HairSystemSettings s;
  s.simulation = r.scene.simulation;
  s.material = r.scene.material;
  s.lutMode = r.lutMode;
  s.strands.guidesOnly = r.guidesOnly;
  s.formats = formats;
  s.look = r.look;
  s.opacity = r.opacity;
  s.raster = r.scene.render.raster;
  s.rasterSettings = r.rasterSettings;
  return s;
}

void validate(const RenderRequest& r) {
  if (r.settleFrames > 100000) throw Error("settle frames must be at most 100000");
  if (!(r.exposure > 0.0f) || !std::isfinite(r.exposure)) throw Error("exposure must be a positive number");
  r.scene.light.validate();  // also catches a hand-built LightSpec that skipped the scene parser
}

FrameCapture captureFrame(const vk::Context& ctx, const HairSystem& hair, const render::OffscreenRenderer& renderer,
                          const DrawView& view) {
  FrameCapture f;
  f.strands = compute::readRenderStrands(ctx, hair.strands(), vk::BufferUse::VertexRead);
  f.verticesPerStrand = hair.strands().layout().verticesPerStrand;
  f.headToWorld = view.headToWorld;
  f.camera = view.camera;
  f.linear = renderer.readLinear();
  if (hair.raster() == RasterMode::Compute)
    f.hairAlpha = render::rgbOfHalfRgba(vk::readbackImage(ctx, hair.rasterImage(), vk::ImageUse::FragmentSampled),
                                        renderer.extent(), 3, 1);
  return f;
}
}  // namespace

RenderResult renderStill(const vk::Context& ctx, const HairAsset& asset, const RenderRequest& request) {
  validate(request);
  const RenderSpec& size = request.scene.render;
  RenderRequest resolved = request;
  resolved.scene.render.raster = resolveRasterMode(request.scene.render.raster, ctx.properties().deviceType);
  render::OffscreenRenderer renderer(ctx, size.width, size.height, size.msaa, resolved.scene.render.raster);
  HairSystem hair(ctx, asset, systemSettings(resolved, renderer.formats()));
  renderer.attach(hair);
  SimulationDriver driver(ctx, hair.simulation(), request.animation, assetHeadRadius(asset));
  if (request.settleFrames > 0) driver.runFrames(request.settleFrames);

  DrawView view;
  view.extent = renderer.extent();
  view.camera = orbitCamera(request.scene.camera, float(size.width) / float(size.height));
  view.light = request.scene.light;
  view.lines = request.lines;
  const HeadMotion motion = driver.nextMotion();
  view.headToWorld = motion.to;
  vk::GpuProfiler profiler(ctx, 16, "render frame");
  vk::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
    profiler.reset(cmd);
    hair.recordUpdate(cmd, motion, &profiler);
    hair.recordPrepareDraw(cmd, view, &profiler);
    renderer.record(cmd, hair, view, request.exposure, &profiler);
  }, "render frame");

  RenderResult result;
  result.width = size.width;
  result.height = size.height;
  result.rgba = renderer.readDisplay();
  result.passTimes = profiler.results();
  result.guides = hair.simulation().guideCount();
  result.strands = hair.strands().layout().strandCount;
  result.verticesPerStrand = hair.strands().layout().verticesPerStrand;
  result.raster = hair.raster();
  if (hair.raster() == RasterMode::Compute) result.rasterStats = hair.rasterStats();
  if (request.captureStrands)
    result.strandDump = compute::renderStrandsToHairData(ctx, hair.strands(), vk::BufferUse::VertexRead,
                                                         "hairpipe render: render strands of the drawn frame");
  if (request.captureFrame) result.frame = captureFrame(ctx, hair, renderer, view);
  if (request.captureOpacity && request.opacity.enabled)
    result.opacity = render::captureOpacity(ctx, hair.shadows().image(), hair.shadows().lightSpace(), request.opacity,
                                            glm::normalize(view.light.direction));
  return result;
}
}  // namespace hp
