// `hairpipe bench opacity [--strands 10000,100000,1000000] [--resolutions 512,1024] [--frames F]
// [--half] [--raster compute,graphics] [--json]`: GPU time of the bounds and opacity passes (GpuProfiler timestamps, median of F
// frames after one warm-up frame) on the default head in its rest pose, for each render-strand count,
// opacity-map resolution and way into the maps (compute splats or graphics lines), measured in one run. Each frame is interpolate -> bounds -> opacity, as HairSystem records it.
#include <algorithm>
#include <cstdio>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/core/error.h"
#include "engine/core/hair/default_head.h"
#include "samples/tools/hair_system.h"
#include "engine/vk/context.h"
#include "engine/vk/submit.h"
#include "samples/cli/bench_context.h"
#include "samples/cli/command.h"
#include "samples/tools/host/json_text.h"

namespace hp::cli::cmd_bench_opacity {  // per subcommand: file-local names stay apart in a unity build

namespace {
struct BenchOptions {
  std::vector<std::uint32_t> strands{10000, 100000, 1000000};
  std::vector<std::uint32_t> resolutions{512, 1024};
  std::uint32_t frames = 3;
  std::vector<std::string> rasters{"compute", "graphics"};
  bool half = false;
  bool deep = false;
  bool json = false;
  std::string device;
};

nlohmann::json benchOne(const hp::vk::Context& ctx, const hp::HairAsset& asset, std::uint32_t resolution,
                        hp::render::OpacityRaster raster, const BenchOptions& o) {
  hp::HairSystemSettings settings;
  settings.opacity.resolution = resolution;
  settings.opacity.raster = raster;
  settings.opacity.deep = o.deep;
  if (o.half) settings.opacity.format = VK_FORMAT_R16G16B16A16_SFLOAT;
  hp::HairSystem hair(ctx, asset, settings);
  hp::DrawView view;
  // simulate, tessellate, interpolate, bounds, opacity (+ first, splat, resolve), head shadow, the bounces
  hp::vk::GpuProfiler profiler(ctx, 16, "bench opacity", hp::vk::StampBarriers::OnCpuDevices);
  std::map<std::string, std::vector<double>> times;
  for (std::uint32_t f = 0; f <= o.frames; ++f) {
    hp::vk::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
      profiler.reset(cmd);
      hair.recordUpdate(cmd, hp::HeadMotion{}, &profiler);
      hair.recordPrepareDraw(cmd, view, &profiler);
    }, "bench opacity frame");
    if (f == 0) continue;  // warm-up
    for (const auto& t : profiler.results()) times[t.name].push_back(t.milliseconds);
  }
  return {{"strands", hair.strands().layout().strandCount},
          {"chunks", hair.strands().layout().chunks.size()},
          {"resolution", resolution},
          {"format", o.half ? "RGBA16F" : "RGBA32F"},
          {"raster", hp::render::opacityRasterName(raster)},
          {"deep", hair.shadows().settings().deep},
          {"bounds_ms", hp::vk::median(times["bounds"])},
          {"opacity_ms", hp::vk::median(times["opacity"])}};
}

void run(const BenchOptions& o) {
  if (o.frames == 0 || o.frames > 100) throw hp::Error("bench opacity: --frames must be in [1, 100]");
  for (std::uint32_t s : o.strands)
    if (s == 0 || s > 4'000'000) throw hp::Error("bench opacity: --strands values must be in [1, 4000000]");
  std::vector<hp::render::OpacityRaster> rasters;
  for (const std::string& r : o.rasters) rasters.push_back(hp::render::parseOpacityRaster(r));
  auto ctx = hp::cli::createBenchContext(o.device, "bench opacity");
  nlohmann::json report = {{"device", ctx->properties().deviceName}, {"frames", o.frames},
                           {"results", nlohmann::json::array()}};
  for (std::uint32_t s : o.strands) {
    hp::DensityOptions density;
    density.totalStrands = s;
    const hp::HairAsset asset = hp::buildDefaultHeadAsset(hp::defaultHeadGrowth(), density);
    for (std::uint32_t r : o.resolutions)
      for (hp::render::OpacityRaster raster : rasters) {
        nlohmann::json row = benchOne(*ctx, asset, r, raster, o);
        if (!o.json)
          std::printf("%8u strands  %4u^2 %s %-8s%s  bounds %8.2f ms  opacity %9.2f ms\n", s, r,
                      row["format"].get<std::string>().c_str(), row["raster"].get<std::string>().c_str(),
                      row["deep"].get<bool>() ? " deep" : "", row["bounds_ms"].get<double>(),
                      row["opacity_ms"].get<double>());
        std::fflush(stdout);
        report["results"].push_back(row);
      }
  }
  if (o.json) std::cout << hp::jsonText(report) << "\n";
}

void setup(CLI::App& app) {
  auto o = std::make_shared<BenchOptions>();
  CLI::App* cmd = hp::cli::benchSuite(app, "opacity", "Time the bounds and opacity-map passes on the device");
  cmd->add_option("--strands", o->strands, "Render strand counts, comma separated")->delimiter(',')->capture_default_str();
  cmd->add_option("--resolutions", o->resolutions, "Opacity map sizes, comma separated")->delimiter(',')->capture_default_str();
  cmd->add_option("--frames", o->frames, "Timed frames per case (median), after one warm-up")->capture_default_str();
  cmd->add_flag("--half", o->half, "RGBA16F opacity maps instead of RGBA32F");
  cmd->add_flag("--deep", o->deep, "Deep opacity maps (the compute path; the graphics path keeps global slices)");
  cmd->add_option("--raster", o->rasters, "Ways into the maps: compute, graphics (comma separated)")
      ->delimiter(',')->capture_default_str();
  cmd->add_flag("--json", o->json, "Print JSON");
  cmd->add_option("--device", o->device, "Vulkan device: index or name substring (env HAIRPIPE_DEVICE)");
  cmd->callback([o] { run(*o); });
}
}  // namespace

HP_CLI_COMMAND(setup);
}  // namespace hp::cli::cmd_bench_opacity
