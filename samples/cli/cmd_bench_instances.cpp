// `hairpipe bench instances [--instances 1,4,16] [--strands N] [--frames F] [--raster MODE] [--json]`: the cost of many heads
// on one hp::Renderer: host time to create the renderer and each instance, device memory held per instance
// and shared (Context::allocatedBytes before and after), and the CPU time to record one frame (update,
// shadows and one view's draw of every instance; median of F frames after one warm-up) for each instance
// count. Every frame is submitted and waited on; only the record calls are timed (host clock: this is CPU
// work). Heads are the default head at `--strands`, side by side. With `--raster compute` the hair of every
// instance goes through the Renderer's compute rasterizer (one target over all instances; the timed record
// calls then include recordRaster and recordComposite). Then the host cost of a material change in the frame
// loop: the setMaterial call on the calling thread, the frames (and ms) until the worker-built tables are
// applied by a frame's recordUpdate, and the record time of that frame (the upload of the tables and, with
// the compute raster, the rebinding of the target's descriptor sets).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include "engine/core/error.h"
#include "engine/core/hair/default_head.h"
#include "engine/core/shading/material_color.h"
#include "compute/renderer/renderer.h"
#include "engine/vk/context.h"
#include "engine/vk/profiler.h"
#include "engine/vk/submit.h"
#include "samples/cli/bench_context.h"
#include "samples/cli/command.h"
#include "samples/tools/offscreen_renderer.h"
#include "samples/tools/host/json_text.h"

namespace hp::cli::cmd_bench_instances {  // per subcommand: file-local names stay apart in a unity build

namespace {
using Clock = std::chrono::steady_clock;

struct BenchOptions {
  std::vector<std::uint32_t> instances{1, 4, 16};
  std::uint32_t strands = 2000;
  std::uint32_t frames = 5;
  std::string raster = "graphics";
  bool json = false;
  std::string device;
};

double msSince(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

struct MaterialChange {
  double callUs = 0.0;      // setMaterial on the calling thread
  std::uint32_t frames = 0; // frames recorded until a recordUpdate applied it
  double appliedMs = 0.0;   // from the call to the end of that frame
  double applyingRecordUs = 0.0;  // the record calls of that frame
};

// A new (uncached) material for `head` during the frame loop; `frame(i)` records and waits for frame i and
// returns its record time in us.
MaterialChange changeMaterial(hp::HairInstance& head, const std::function<double(std::uint32_t)>& frame) {
  hp::HairMaterial material = head.settings().material;
  material.absorption = hp::absorptionFromColor({0.85, 0.7, 0.45});  // blonde: tables not built yet
  MaterialChange c;
  const auto t0 = Clock::now();
  head.setMaterial(material, head.settings().lutMode);
  c.callUs = msSince(t0) * 1000.0;
  while (head.materialPending() && c.frames < 1000) c.applyingRecordUs = frame(c.frames++);
  c.appliedMs = msSince(t0);
  return c;
}

nlohmann::json benchCount(const hp::vk::Context& ctx, const hp::HairAsset& asset, std::uint32_t count,
                          const BenchOptions& o, hp::RasterMode raster) {
  hp::render::OffscreenRenderer target(ctx, 320, 180, 1, raster);
  hp::RendererSettings settings;
  settings.formats = target.formats();
  settings.raster = raster;
  const std::uint64_t before = ctx.allocatedBytes();
  auto t0 = Clock::now();
  hp::Renderer renderer(ctx, settings);
  const double rendererMs = msSince(t0);
  const std::uint64_t shared = ctx.allocatedBytes() - before;
  std::vector<std::unique_ptr<hp::HairInstance>> heads;
  std::vector<double> instanceMs;
  for (std::uint32_t i = 0; i < count; ++i) {
    t0 = Clock::now();
    heads.push_back(renderer.createInstance(asset, {}, glm::translate(glm::mat4(1.0f), {0.3f * float(i), 0, 0})));
    instanceMs.push_back(msSince(t0));
  }
  const std::uint64_t all = ctx.allocatedBytes() - before;
  std::vector<hp::HairInstance*> span;
  for (auto& h : heads) span.push_back(h.get());
  if (raster == hp::RasterMode::Compute) target.attach(renderer, span);
  hp::CameraSpec cam;
  cam.distance = 1.0f + 0.3f * float(count);
  const hp::View view{hp::orbitCamera(cam, 320.0f / 180.0f), {320, 180}, false, 0};
  std::vector<double> recordUs;
  const auto recordFrame = [&](std::uint32_t f) {
    double us = 0.0;
    hp::vk::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
      auto t = Clock::now();
      renderer.recordUpdate(cmd, f, span);
      renderer.recordShadows(cmd, f, hp::LightSpec{}, span);
      us += msSince(t) * 1000.0;
      if (raster == hp::RasterMode::Compute) {
        t = Clock::now();
        target.record(cmd, renderer, f, view, span, 1.0f);
        us += msSince(t) * 1000.0;
        return;
      }
      target.record(cmd, [&](VkCommandBuffer c) {
        auto td = Clock::now();
        renderer.recordDraw(c, f, view, span);
        us += msSince(td) * 1000.0;
      }, 1.0f);
    }, "bench instances frame");
    return us;
  };
  for (std::uint32_t f = 0; f <= o.frames; ++f) {
    const double us = recordFrame(f);
    if (f > 0) recordUs.push_back(us);  // frame 0 is the warm-up
  }
  const MaterialChange change = changeMaterial(*heads.front(), [&](std::uint32_t f) { return recordFrame(o.frames + 1 + f); });
  const double later = count > 1 ? hp::vk::median(std::vector<double>(instanceMs.begin() + 1, instanceMs.end())) : 0.0;
  return {{"instances", count},
          {"renderer_create_ms", rendererMs},
          {"first_instance_ms", instanceMs.front()},
          {"later_instance_ms_median", later},
          {"shared_bytes", shared},
          {"per_instance_bytes", (all - shared) / count},
          {"record_us_median", hp::vk::median(recordUs)},
          {"material_call_us", change.callUs},
          {"material_frames_until_applied", change.frames},
          {"material_ms_until_applied", change.appliedMs},
          {"material_applying_record_us", change.applyingRecordUs}};
}

void run(const BenchOptions& o) {
  if (o.frames == 0 || o.frames > 100) throw hp::Error("bench instances: --frames must be in [1, 100]");
  if (o.strands == 0 || o.strands > 1'000'000) throw hp::Error("bench instances: --strands must be in [1, 1000000]");
  for (std::uint32_t n : o.instances)
    if (n == 0 || n > 64) throw hp::Error("bench instances: --instances values must be in [1, 64]");
  const hp::RasterMode requested = hp::parseRasterMode(o.raster);
  auto ctx = hp::cli::createBenchContext(o.device, "bench instances");
  const hp::RasterMode raster = hp::resolveRasterMode(requested, ctx->properties().deviceType);
  hp::DensityOptions density;
  density.totalStrands = o.strands;
  const hp::HairAsset asset = hp::buildDefaultHeadAsset(hp::defaultHeadGrowth(), density);
  nlohmann::json report = {{"device", ctx->properties().deviceName}, {"strands", o.strands}, {"frames", o.frames},
                           {"raster", hp::rasterModeName(raster)},
                           {"results", nlohmann::json::array()}};
  for (std::uint32_t n : o.instances) {
    nlohmann::json row = benchCount(*ctx, asset, n, o, raster);
    if (!o.json)
      std::printf("%3u instances  renderer %7.1f ms  1st instance %7.1f ms  later %7.1f ms  shared %6.2f MiB  "
                  "per instance %6.2f MiB  record %8.1f us  setMaterial %6.1f us, applied after %u frames "
                  "(%.1f ms; that frame's record %.1f us)\n",
                  n, row["renderer_create_ms"].get<double>(), row["first_instance_ms"].get<double>(),
                  row["later_instance_ms_median"].get<double>(), row["shared_bytes"].get<double>() / 1048576.0,
                  row["per_instance_bytes"].get<double>() / 1048576.0, row["record_us_median"].get<double>(),
                  row["material_call_us"].get<double>(), row["material_frames_until_applied"].get<std::uint32_t>(),
                  row["material_ms_until_applied"].get<double>(), row["material_applying_record_us"].get<double>());
    std::fflush(stdout);
    report["results"].push_back(row);
  }
  if (o.json) std::cout << hp::jsonText(report) << "\n";
}

void setup(CLI::App& app) {
  auto o = std::make_shared<BenchOptions>();
  CLI::App* cmd = hp::cli::benchSuite(app, "instances", "Time renderer/instance creation and frame recording for many heads");
  cmd->add_option("--instances", o->instances, "Instance counts, comma separated")->delimiter(',')->capture_default_str();
  cmd->add_option("--strands", o->strands, "Render strands per head")->capture_default_str();
  cmd->add_option("--frames", o->frames, "Timed frames per count (median), after one warm-up")->capture_default_str();
  cmd->add_option("--raster", o->raster, "Hair drawing: graphics, compute or auto")->capture_default_str();
  cmd->add_flag("--json", o->json, "Print JSON");
  cmd->add_option("--device", o->device, "Vulkan device: index or name substring (env HAIRPIPE_DEVICE)");
  cmd->callback([o] { run(*o); });
}
}  // namespace

HP_CLI_COMMAND(setup);
}  // namespace hp::cli::cmd_bench_instances
