#include "samples/cli/bench_frame.h"

#include <algorithm>
#include <chrono>
#include <cstdio>

#include "samples/cli/frame_options.h"
#include "samples/tools/hair_system.h"
#include "samples/tools/host/process_use.h"
#include "samples/tools/offscreen_renderer.h"
#include "samples/tools/copy_reference.h"
#include "engine/vk/submit.h"
#include "shaders/shared/opacity.h"
#include "shaders/shared/raster.h"

namespace hp::cli {
namespace {
constexpr VkDeviceSize kCopyBytes = 64ull << 20;

PassTiming summarize(std::vector<double> ms) {
  PassTiming t;
  t.medianMs = vk::median(ms);
  t.minMs = *std::min_element(ms.begin(), ms.end());
  t.maxMs = *std::max_element(ms.begin(), ms.end());
  return t;
}

// Resident set of this process (0 where it cannot be read).
double residentMiB() { return double(residentBytes()) / (1024.0 * 1024.0); }

// Compulsory bytes per frame of the compute passes: every input read once, every output written once
// (formulas as bench strands / bench sim; raster: vertex records 16 + 8 bytes, list entries 8 bytes; the
// shade step is counted as if every vertex were listed; compute opacity: positions, the bins in effect
// cleared and read by the resolve, the maps written (16 bytes a slice layer and the first-hair layer), deep
// maps' first-hair buffer cleared and read, the atomics not counted). Interpolate
// and bounds work on every strand; the raster and opacity passes on the level of detail's drawn ones.
void countBytes(FrameResult& r, const compute::StrandLayout& l) {
  const double g = l.guideCount, p = l.particlesPerGuide, q = l.verticesPerStrand, all = l.strandCount;
  const double s = lodStrandCount(r.c.lodFraction, l.strandCount);
  const double v = s * q, e = double(r.rasterEntries);
  const double tiles = double((r.c.width + 7) / 8) * double((r.c.height + 7) / 8);
  const double pixels = double(r.c.width) * r.c.height;
  const double mapTexels = double(render::OpacitySettings{}.resolution) * render::OpacitySettings{}.resolution;
  std::map<std::string, double> bytes = {
      {"simulate", g * p * 16 * 5},
      {"tessellate", g * p * 16 + g * q * 32},
      {"interpolate", all * 16 + l.triangleCount * 16.0 + g * q * 32 + all * (q * 32 + 16)},
      {"bounds", all * q * 16},
      {"raster shade", v * (32 + 8 + 4) + s * 16},
      {"raster project", v * 32 + s * 16},
      {"raster bin", 2 * v * 16 + tiles * gpu::RASTER_DEPTH_BINS * 16 + e * 8},
      {"raster fine", e * 8 + e * 2 * 16 + pixels * (4 + 8)},
  };
  if (r.opacityRaster == render::OpacityRaster::Compute)
    bytes["opacity"] = v * 16 + 2 * r.opacityBufferBytes + mapTexels * gpu::OPACITY_LAYERS * 16;
  for (auto& [name, t] : r.passes)
    if (auto it = bytes.find(name); it != bytes.end()) t.bytes = it->second;
}
// `count` shadowed directional lights: the scene's sun, then a rim from behind, a fill from the left and a
// light from above, each dimmer.
std::vector<LightSpec> benchLights(std::uint32_t count) {
  const glm::vec3 directions[] = {LightSpec{}.direction, {-0.3f, 0.4f, -0.87f}, {-0.9f, 0.1f, 0.42f}, {0.1f, 1.0f, 0.05f}};
  std::vector<LightSpec> lights;
  for (std::uint32_t i = 0; i < count && i < 4; ++i) {
    LightSpec l;
    l.direction = glm::normalize(directions[i]);
    l.intensity = i == 0 ? l.intensity : 1.0f;
    lights.push_back(l);
  }
  return lights;
}
}  // namespace

void prepareBenchModel(FrameCase& c, const Scene& base) {
  auto scene = std::make_shared<Scene>(base);
  scene->render.width = c.width;
  scene->render.height = c.height;
  scene->density.mode = c.ownStrands ? DensityOptions::Mode::Guides : DensityOptions::Mode::Total;
  if (!c.ownStrands) scene->density.totalStrands = c.strands;
  auto asset = std::make_shared<const HairAsset>(buildSceneAsset(*scene));
  frameCamera(*scene, *asset);  // a model without a scene: the camera framed on its hair
  c.scene = std::move(scene);
  c.asset = std::move(asset);
}

FrameResult benchFrame(const vk::Context& ctx, const FrameCase& c) {
  const Scene& scene = *c.scene;
  const HairAsset& asset = *c.asset;
  render::OffscreenRenderer renderer(ctx, c.width, c.height, c.msaa, c.raster);
  HairSystemSettings settings;
  settings.formats = renderer.formats();
  settings.raster = c.raster;
  settings.opacity.raster = c.opacityRaster;
  settings.opacity.shadowStrands = c.shadowStrands;
  settings.look.skinBounce = c.skinBounce;
  settings.look.skinIndirect = c.skinIndirect;
  settings.strands.bounceSamples = c.bounceSamples;
  settings.rasterSettings.fineWalk = c.fineWalk;
  settings.rasterSettings.shadingSpacing = c.shadingSpacing;
  settings.rasterSettings.growLists = c.growLists;
  settings.look.scattering = c.scattering;
  settings.lutMode = c.lutMode;
  settings.material = c.material;
  settings.groom = c.groom ? scene.groom : GroomSettings{};
  settings.simulation = scene.simulation;
  const std::vector<LightSpec> lights = benchLights(c.lights);
  settings.shadowedLights = shadowSlotsFor(lights);
  if (c.lodFraction < 1.0f) settings.lod = {true, 0.0f, 1e-3f, c.lodFraction};  // that fraction at any distance
  HairSystem hair(ctx, asset, settings);
  const std::uint64_t beforeTarget = ctx.allocatedBytes();
  renderer.attach(hair);  // the compute raster's target (lists and images of this extent and strand count)
  const std::int64_t targetBytes = std::int64_t(ctx.allocatedBytes()) - std::int64_t(beforeTarget);
  DrawView view;
  view.extent = renderer.extent();
  view.camera = orbitCamera(scene.camera, float(c.width) / float(c.height));
  view.lights = lights;
  vk::CopyReference copy(ctx, kCopyBytes);
  std::map<std::string, std::vector<double>> times;
  std::vector<double> hostMs;
  std::vector<double> residentAfter;  // after each frame, warm-up included
  const std::uint64_t beforeFrames = ctx.allocatedBytes();
  for (std::uint32_t f = 0; f <= c.frames; ++f) {  // frame 0 warms up
    vk::GpuProfiler profiler(ctx, 64, "bench frame",  // scopes: the passes, six per shadowed light
                              vk::StampBarriers::OnCpuDevices);
    const auto start = std::chrono::steady_clock::now();
    vk::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
      profiler.reset(cmd);
      copy.record(cmd, profiler);  // first: lavapipe stamps scopes after graphics work late (docs/PERFORMANCE.md)
      hair.recordUpdate(cmd, HeadMotion{}, &profiler);
      hair.recordPrepareDraw(cmd, view, &profiler);
      renderer.record(cmd, hair, view, 1.0f, &profiler);
    }, "bench frame");
    hostMs.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    residentAfter.push_back(residentMiB());
    if (f == 0) {
      hostMs.clear();
      continue;
    }
    double frameMs = 0.0;  // every top-level scope but the reference copy
    std::map<std::string, double> frameTimes;  // a pass that runs per shadowed light counts once, summed
    for (const auto& t : profiler.results()) {
      frameTimes[t.name] += t.milliseconds;
      if (t.depth == 0 && t.name != "copy") frameMs += t.milliseconds;
    }
    for (const auto& [name, ms] : frameTimes) times[name].push_back(ms);
    times["frame"].push_back(frameMs);
  }
  FrameResult r;
  r.c = c;
  r.c.strands = hair.strands().layout().strandCount;  // the model's own count with ownStrands
  r.hostMs = vk::median(hostMs);
  r.residentMiB = residentAfter.back();
  // The target as the frames left it: growing lists were replaced by larger ones during the frames.
  r.rasterTargetMiB = double(targetBytes + (std::int64_t(ctx.allocatedBytes()) - std::int64_t(beforeFrames))) /
                      (1024.0 * 1024.0);
  // Over the second half of the timed frames: on lavapipe resident memory still grows for the first two
  // or three frames after the warm-up (the driver's worker threads reach their working size; 452 -> 522 MiB
  // at 20k strands, then flat to the frame), which is not a per-frame cost.
  const std::size_t half = c.frames / 2;
  r.residentGrowthMiB = (residentAfter.back() - residentAfter[half]) / double(c.frames - half);
  for (auto& [name, ms] : times) r.passes[name] = summarize(ms);
  if (hair.raster() == RasterMode::Compute) {
    const compute::RasterStats stats = hair.rasterStats();
    r.rasterEntries = stats.kept;
    r.rasterOverflow = stats.overflow();
    r.fineWalkRun = stats.walk;
    r.shadedVertices = stats.shaded;
  }
  r.opacityRaster = hair.shadows().raster();
  if (const compute::OpacityResolvePass* resolve = hair.shadows().resolvePass())
    r.opacityBufferBytes = double(resolve->bins().size() + (resolve->deep() ? resolve->first().size() : 0));
  r.copyBytes = copy.bytesMoved();
  r.copyAlone = copy.measureAlone();
  r.unresolvedBecause = vk::timestampsUnresolvedBecause(r.copyAlone, r.passes.at("copy").medianMs);
  r.timestampsResolvePasses = r.unresolvedBecause.empty();
  countBytes(r, hair.strands().layout());
  return r;
}
}  // namespace hp::cli
