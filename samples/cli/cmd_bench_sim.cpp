// `hairpipe bench sim`: GPU ms per frame of the simulation pass for 1k / 10k / 100k guides (the default
// head's guides repeated), and its achieved bytes/s as a fraction of vkCmdCopyBuffer bandwidth measured
// in the same run. Bytes counted per frame: positions and previous read + written, rest pose read.
// --colliders picks what the hair collides with: the default head's distance grid (sdf, default),
// seven spheres roughly covering the same head and shoulders (spheres), or nothing (none). --grid on, off
// or both (default): the hair grid (docs/THEORY.md §2.7) at its recommended values or off; with it on, its
// own passes (clear, splat, resolve) are timed apart as grid_ms and are not in ms or the bytes.
#include <algorithm>
#include <iostream>

#include <nlohmann/json.hpp>

#include "compute/strands/simulate_pass.h"
#include "engine/core/error.h"
#include "engine/core/hair/default_head.h"
#include "engine/vk/barriers.h"
#include "engine/vk/context.h"
#include "samples/tools/copy_reference.h"
#include "engine/vk/submit.h"
#include "samples/cli/command.h"
#include "samples/cli/bench_context.h"
#include "samples/tools/host/json_text.h"

namespace hp::cli::cmd_bench_sim {  // per subcommand: file-local names stay apart in a unity build

namespace {
struct BenchOptions {
  std::string device;
  std::vector<std::uint32_t> guides{1000, 10000, 100000};
  std::uint32_t frames = 20;
  std::string colliders = "sdf";
  std::string grid = "both";
  bool json = false;
};

// Cranium, face, neck (2), chest and shoulders (2): the cheap stand-in for the head's field.
const std::vector<hp::SphereCollider> kHeadSpheres = {
    {{0.0f, 0.0f, -0.01f}, 0.090f},    {{0.0f, -0.055f, 0.025f}, 0.065f}, {{0.0f, -0.140f, -0.02f}, 0.052f},
    {{0.0f, -0.200f, -0.02f}, 0.055f}, {{0.0f, -0.330f, -0.02f}, 0.100f}, {{0.12f, -0.28f, -0.02f}, 0.07f},
    {{-0.12f, -0.28f, -0.02f}, 0.07f}};

hp::HairAsset repeatedGuides(const hp::HairAsset& head, std::uint32_t count, const std::string& colliders) {
  hp::HairAsset asset;
  if (colliders == "sdf") asset.sdf = head.sdf;
  else if (colliders == "spheres") asset.colliders = kHeadSpheres;
  else if (colliders != "none") throw hp::Error("--colliders must be sdf, spheres or none, got '" + colliders + "'");
  asset.guides.particlesPerGuide = head.guides.particlesPerGuide;
  for (std::uint32_t g = 0; g < count; ++g)
    for (const auto& p : head.guides.guide(g % head.guides.guideCount())) asset.guides.positions.push_back(p);
  return asset;
}

// The defaults, with the hair grid off or at its recommended values (docs/THEORY.md §2.7).
hp::SimulationParams benchParams(bool grid) { return grid ? hp::withHairGrid({}) : hp::SimulationParams{}; }

nlohmann::json benchOne(const hp::vk::Context& ctx, const hp::HairAsset& asset, std::uint32_t frames,
                        const hp::vk::CopyReference& copy, bool grid) {
  hp::SimulatePass pass(ctx, asset, benchParams(grid));
  hp::vk::GpuProfiler profiler(ctx, 3 * frames + 3, "bench sim", hp::vk::StampBarriers::OnCpuDevices);
  std::vector<double> sim, gridMs, copyMs;
  for (std::uint32_t f = 0; f < frames; ++f) {
    hp::vk::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
      profiler.reset(cmd);
      hp::vk::memoryBarrier(ctx, cmd, hp::vk::BufferUse::ComputeWrite, hp::vk::BufferUse::ComputeWrite);
      pass.record(cmd, {glm::mat4(1.0f), glm::mat4(1.0f), f / 60.0, false}, &profiler);
      copy.record(cmd, profiler);
    }, "bench sim frame");
    for (const auto& t : profiler.results())
      (t.name == "simulate" ? sim : t.name == "simulate grid" ? gridMs : copyMs).push_back(t.milliseconds);
  }
  const double particles = double(asset.guides.positions.size());
  const double bytes = particles * 16.0 * 5.0;
  const double simMs = hp::vk::median(sim);
  // Bandwidth against the copy alone, and only where the timestamps resolve the passes.
  const hp::vk::CopyTiming alone = copy.measureAlone();
  const std::string why = hp::vk::timestampsUnresolvedBecause(alone, hp::vk::median(copyMs));
  const double copyGbs = hp::vk::copyGigabytesPerSecond(alone);
  nlohmann::json r = {{"guides", asset.guides.guideCount()}, {"grid", grid}, {"particles", particles}, {"ms", simMs},
                      {"grid_ms", grid ? nlohmann::json(hp::vk::median(gridMs)) : nlohmann::json(nullptr)}, {"bytes", bytes},
                      {"copy_gb_per_s", copyGbs}, {"timestamps_resolve_passes", why.empty()}, {"unresolved_because", why}};
  if (why.empty()) {
    const double simGbs = hp::vk::gigabytesPerSecond(bytes, simMs);
    r["gb_per_s"] = simGbs;
    r["fraction_of_copy"] = simGbs / copyGbs;
  }
  return r;
}

void runBench(const BenchOptions& o) {
  if (o.grid != "on" && o.grid != "off" && o.grid != "both")
    throw hp::Error("--grid must be on, off or both, got '" + o.grid + "'");
  if (o.frames == 0 || o.frames > 10000) throw hp::Error("--frames must be in [1, 10000]");
  auto ctx = hp::cli::createBenchContext(o.device, "bench sim");
  const hp::HairAsset head = hp::buildDefaultHeadAsset();
  hp::vk::CopyReference copy(*ctx, 64ull << 20);
  nlohmann::json report = {{"device", ctx->properties().deviceName},
                           {"iterations", hp::SimulationParams{}.iterations},
                           {"substeps", hp::SimulationParams{}.substeps},
                           {"colliders", o.colliders},
                           {"results", nlohmann::json::array()}};
  for (std::uint32_t g : o.guides) {
    if (g == 0 || g > 4000000) throw hp::Error("--guides values must be in [1, 4000000]");
    const hp::HairAsset asset = repeatedGuides(head, g, o.colliders);
    if (o.grid != "on") report["results"].push_back(benchOne(*ctx, asset, o.frames, copy, false));
    if (o.grid != "off") report["results"].push_back(benchOne(*ctx, asset, o.frames, copy, true));
  }
  if (o.json) {
    std::cout << hp::jsonText(report) << "\n";
    return;
  }
  std::cout << "simulation on " << report["device"].get<std::string>() << " (median of " << o.frames
            << " frames, colliders: " << o.colliders << ")\n"
            << "guides    grid ms   ms/frame   GB/s   copy GB/s  of copy\n";
  for (const auto& r : report["results"]) {
    const std::string grid = r["grid"].get<bool>() ? std::to_string(r["grid_ms"].get<double>()).substr(0, 7) : "off";
    if (!r["timestamps_resolve_passes"].get<bool>()) {
      std::printf("%-9u %-9s %-10.3f (no bandwidth derived: %s)\n", r["guides"].get<unsigned>(), grid.c_str(),
                  r["ms"].get<double>(), r["unresolved_because"].get<std::string>().c_str());
      continue;
    }
    std::printf("%-9u %-9s %-10.3f %-6.3f %-10.2f %.1f%%\n", r["guides"].get<unsigned>(), grid.c_str(),
                r["ms"].get<double>(), r["gb_per_s"].get<double>(), r["copy_gb_per_s"].get<double>(),
                100.0 * r["fraction_of_copy"].get<double>());
  }
}

void setupBench(CLI::App& app) {
  auto o = std::make_shared<BenchOptions>();
  CLI::App* cmd = hp::cli::benchSuite(app, "sim", "Benchmark the simulation pass with GPU timestamps");
  cmd->add_option("--device", o->device, "Vulkan device: index or name substring (env HAIRPIPE_DEVICE)");
  cmd->add_option("--guides", o->guides, "Guide counts to measure (default 1000 10000 100000)");
  cmd->add_option("--frames", o->frames, "Frames per measurement (median is reported)");
  cmd->add_option("--colliders", o->colliders, "sdf (the default head's distance grid), spheres or none (default sdf)");
  cmd->add_option("--grid", o->grid, "The hair grid: on, off or both (default both)");
  cmd->add_flag("--json", o->json, "Print JSON");
  cmd->callback([o] { runBench(*o); });
}
}  // namespace

HP_CLI_COMMAND(setupBench);
}  // namespace hp::cli::cmd_bench_sim
