// `hairpipe bench sim`: GPU ms per frame of the simulation pass for 1k / 10k / 100k guides (the default
// head's guides repeated), and its achieved bytes/s as a fraction of vkCmdCopyBuffer bandwidth measured
// in the same run. Bytes counted per frame: positions and previous read + written, rest pose read.
// --colliders picks what the hair collides with: the default head's distance grid (sdf, default),
// seven spheres roughly covering the same head and shoulders (spheres), or nothing (none).
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

namespace hp::cli::cmd_bench_sim {  // per subcommand: file-local names stay apart in a unity build

namespace {
struct BenchOptions {
  std::string device;
  std::vector<std::uint32_t> guides{1000, 10000, 100000};
  std::uint32_t frames = 20;
  std::string colliders = "sdf";
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

nlohmann::json benchOne(const hp::vk::Context& ctx, const hp::HairAsset& asset, std::uint32_t frames,
                        const hp::vk::CopyReference& copy) {
  hp::SimulatePass pass(ctx, asset, hp::SimulationParams{});
  hp::vk::GpuProfiler profiler(ctx, 2 * frames + 2, "bench sim");
  std::vector<double> sim, copyMs;
  for (std::uint32_t f = 0; f < frames; ++f) {
    hp::vk::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
      profiler.reset(cmd);
      hp::vk::memoryBarrier(ctx, cmd, hp::vk::BufferUse::ComputeWrite, hp::vk::BufferUse::ComputeWrite);
      pass.record(cmd, {glm::mat4(1.0f), glm::mat4(1.0f), f / 60.0, false}, &profiler);
      copy.record(cmd, profiler);
    }, "bench sim frame");
    auto times = profiler.results();
    sim.push_back(times[0].milliseconds);
    copyMs.push_back(times[1].milliseconds);
  }
  const double particles = double(asset.guides.positions.size());
  const double bytes = particles * 16.0 * 5.0;
  const double simMs = hp::vk::median(sim);
  // Bandwidth against the copy alone, and only where the timestamps resolve the passes.
  const hp::vk::CopyTiming alone = copy.measureAlone();
  const std::string why = hp::vk::timestampsUnresolvedBecause(alone, hp::vk::median(copyMs));
  const double copyGbs = hp::vk::gigabytesPerSecond(copy.bytesMoved(), alone.medianMs);
  nlohmann::json r = {{"guides", asset.guides.guideCount()}, {"particles", particles}, {"ms", simMs}, {"bytes", bytes},
                      {"copy_gb_per_s", copyGbs}, {"timestamps_resolve_passes", why.empty()}, {"unresolved_because", why}};
  if (why.empty()) {
    const double simGbs = hp::vk::gigabytesPerSecond(bytes, simMs);
    r["gb_per_s"] = simGbs;
    r["fraction_of_copy"] = simGbs / copyGbs;
  }
  return r;
}

void runBench(const BenchOptions& o) {
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
    report["results"].push_back(benchOne(*ctx, repeatedGuides(head, g, o.colliders), o.frames, copy));
  }
  if (o.json) {
    std::cout << report.dump(2) << "\n";
    return;
  }
  std::cout << "simulation on " << report["device"].get<std::string>() << " (median of " << o.frames
            << " frames, colliders: " << o.colliders << ")\n"
            << "guides    ms/frame   GB/s   copy GB/s  of copy\n";
  for (const auto& r : report["results"]) {
    if (!r["timestamps_resolve_passes"].get<bool>()) {
      std::printf("%-9u %-10.3f (no bandwidth derived: %s)\n", r["guides"].get<unsigned>(), r["ms"].get<double>(),
                  r["unresolved_because"].get<std::string>().c_str());
      continue;
    }
    std::printf("%-9u %-10.3f %-6.3f %-10.2f %.1f%%\n", r["guides"].get<unsigned>(), r["ms"].get<double>(),
                r["gb_per_s"].get<double>(), r["copy_gb_per_s"].get<double>(),
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
  cmd->add_flag("--json", o->json, "Print JSON");
  cmd->callback([o] { runBench(*o); });
}
}  // namespace

HP_CLI_COMMAND(setupBench);
}  // namespace hp::cli::cmd_bench_sim
