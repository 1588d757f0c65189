// `hairpipe bench strands [--strands 10000,100000,1000000] [--frames F] [--vertices Q] [--walk auto,strand,vertex]
// [--no-groom] [--clump ..] [--curl ..] [--frizz ..] [--json]`: GPU time per frame of the tessellate and
// interpolate passes (GpuProfiler timestamps, median of F frames after one warm-up frame) on the default head, with
// the scenes' groom and the groom options, at each render-strand count and interpolate walk
// (compute::InterpolateWalk; "vertex" stages groomed strands), and the achieved bandwidth as a fraction of the copy yardstick's (the faster
// of a vkCmdCopyBuffer of 128 MiB and a shader's copy, each timed alone: samples/tools/copy_reference.h).
// Bytes counted per pass are the compulsory traffic: every input read once, every output written once
//   tessellate:  G*P*16 read + G*Q*32 written
//   interpolate: S*16 bindings + T*16 triangles + G*Q*32 smoothed guides read + S*(Q*32 + 16) written (the
//                plain blend's; a groomed strand reads no guide tangents, but its clump centre's positions)
//   copy:        2 * 128 MiB (read + write)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "samples/tools/strand_dump.h"
#include "engine/core/error.h"
#include "engine/core/hair/default_head.h"
#include "engine/vk/barriers.h"
#include "engine/vk/context.h"
#include "samples/tools/copy_reference.h"
#include "engine/vk/submit.h"
#include "samples/cli/groom_options.h"
#include "samples/cli/bench_context.h"
#include "samples/cli/command.h"
#include "samples/tools/host/json_text.h"

namespace hp::cli::cmd_bench_strands {  // per subcommand: file-local names stay apart in a unity build

namespace {
constexpr VkDeviceSize kCopyBytes = 128ull << 20;

struct BenchOptions {
  std::vector<std::uint32_t> strands{10000, 100000, 1000000};
  std::uint32_t frames = 5;
  std::uint32_t vertices = hp::compute::kDefaultVerticesPerStrand;
  std::vector<std::string> walks{"auto"};
  bool json = false;
  std::string device;
  hp::cli::GroomOptions groomOptions;
  hp::GroomSettings groom = hp::recommendedGroom();  // the scenes' groom, then groomOptions
};

struct Result {
  hp::compute::StrandLayout layout;
  hp::compute::InterpolateWalk walk = hp::compute::InterpolateWalk::Auto;
  std::string walkTaken = "strand";  // the walk the pass took (InterpolatePass::walkTaken)
  double tessellateMs = 0, interpolateMs = 0, copyMs = 0;
  double frameWallMs = 0;  // host wall clock of a whole frame submission (sanity check of the timestamps)
  hp::vk::CopyTiming copyAlone;  // the yardstick: the copy in submissions of its own
  std::string unresolvedBecause;  // why the timestamps do not resolve the passes (empty: they do)
  double tessellateBytes = 0, interpolateBytes = 0;
};

void countBytes(Result& r) {
  const auto& l = r.layout;
  const double g = l.guideCount, p = l.particlesPerGuide, q = l.verticesPerStrand, s = l.strandCount;
  r.tessellateBytes = g * p * 16 + g * q * 32;
  r.interpolateBytes = s * 16 + l.triangleCount * 16.0 + g * q * 32 + s * (q * 32 + 16);
}

// One frame: the previous frame's writes are done (the frame recorder's barrier), then the passes,
// then the reference copy.
void recordFrame(const hp::vk::Context& ctx, VkCommandBuffer cmd, hp::vk::GpuProfiler& profiler,
                 const hp::compute::TessellatePass& tessellate, const hp::compute::InterpolatePass& interpolate,
                 const hp::vk::CopyReference& copy) {
  profiler.reset(cmd);
  hp::vk::memoryBarrier(ctx, cmd, hp::vk::BufferUse::ComputeWrite, hp::vk::BufferUse::ComputeWrite);
  hp::compute::recordStrandPasses(ctx, cmd, tessellate, interpolate, &profiler);
  copy.record(cmd, profiler);
}

Result benchOne(const hp::vk::Context& ctx, std::uint32_t strands, hp::compute::InterpolateWalk walk, const BenchOptions& o) {
  hp::DensityOptions density;
  density.totalStrands = strands;
  hp::HairAsset asset = hp::buildDefaultHeadAsset(hp::defaultHeadGrowth(), density);
  const hp::GuideSet& guides = asset.guides;
  hp::compute::StrandOptions options;
  options.verticesPerStrand = o.vertices;
  hp::compute::StrandBuffers buffers(ctx, guides.guideCount(), guides.particlesPerGuide, asset.topology, options);
  hp::vk::Buffer particles = hp::compute::uploadGuideParticles(ctx, guides);
  hp::compute::TessellatePass tessellate(ctx, particles, buffers);
  hp::compute::InterpolatePass interpolate(ctx, buffers, nullptr, o.groom, walk);
  hp::vk::CopyReference copy(ctx, kCopyBytes);
  hp::vk::GpuProfiler profiler(ctx, 8, "bench strands", hp::vk::StampBarriers::OnCpuDevices);
  std::map<std::string, std::vector<double>> times;
  for (std::uint32_t f = 0; f <= o.frames; ++f) {  // frame 0 warms up (first touch of the memory)
    const auto start = std::chrono::steady_clock::now();
    hp::vk::submitAndWait(ctx, [&](VkCommandBuffer cmd) { recordFrame(ctx, cmd, profiler, tessellate, interpolate, copy); },
                          "bench strands frame");
    const double wallMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    if (f == 0) continue;
    times["wall"].push_back(wallMs);
    for (const auto& t : profiler.results()) times[t.name].push_back(t.milliseconds);
  }
  Result r;
  r.layout = buffers.layout();
  r.walk = walk;
  r.walkTaken = interpolate.walkTaken();
  r.tessellateMs = hp::vk::median(times["tessellate"]);
  r.interpolateMs = hp::vk::median(times["interpolate"]);
  r.copyMs = hp::vk::median(times["copy"]);
  r.frameWallMs = hp::vk::median(times["wall"]);
  r.copyAlone = copy.measureAlone();
  r.unresolvedBecause = hp::vk::timestampsUnresolvedBecause(r.copyAlone, r.copyMs);
  countBytes(r);
  return r;
}

double gbPerSecond(double bytes, double ms) { return hp::vk::gigabytesPerSecond(bytes, ms); }

// Bandwidth against the copy alone, and only where the timestamps resolve the passes.
nlohmann::json toJson(const Result& r) {
  const double copyGbs = hp::vk::copyGigabytesPerSecond(r.copyAlone);
  const bool resolved = r.unresolvedBecause.empty();
  auto pass = [&](double ms, double bytes) {
    nlohmann::json p{{"ms", ms}, {"bytes", bytes}};
    if (resolved) p["gb_per_s"] = gbPerSecond(bytes, ms), p["fraction_of_copy"] = gbPerSecond(bytes, ms) / copyGbs;
    return p;
  };
  return {{"strands", r.layout.strandCount},
          {"guides", r.layout.guideCount},
          {"vertices_per_strand", r.layout.verticesPerStrand},
          {"chunks", r.layout.chunks.size()},
          {"walk", hp::compute::interpolateWalkName(r.walk)},
          {"per_vertex", r.walkTaken != "strand"},  // the stores went per vertex (plain or staged)
          {"walk_taken", r.walkTaken},
          {"tessellate", pass(r.tessellateMs, r.tessellateBytes)},
          {"interpolate", pass(r.interpolateMs, r.interpolateBytes)},
          {"copy", {{"ms", r.copyMs}, {"bytes", 2.0 * kCopyBytes}, {"alone_ms", r.copyAlone.medianMs},
                    {"alone_gb_per_s", copyGbs}, {"alone_runs", r.copyAlone.runs},
                    {"transfer_gb_per_s", gbPerSecond(r.copyAlone.bytes, r.copyAlone.medianMs)},
                    {"compute_gb_per_s", gbPerSecond(r.copyAlone.computeBytes, r.copyAlone.computeMs)}}},
          {"timestamps_resolve_passes", resolved},
          {"unresolved_because", r.unresolvedBecause},
          {"frame_wall_ms", r.frameWallMs}};
}

void printText(const nlohmann::json& report) {
  std::cout << "device: " << report["device"].get<std::string>() << ", median of " << report["frames"]
            << " frames\n";
  std::cout << "strands  chunks  walk          tessellate ms  interpolate ms  interp GB/s  of copy  copy GB/s  frame wall ms\n";
  for (const auto& r : report["results"]) {
    char line[200];
    const bool resolved = r["timestamps_resolve_passes"].get<bool>();
    const nlohmann::json& interp = r["interpolate"];
    const std::string walk = r["walk"].get<std::string>() + " (" + r["walk_taken"].get<std::string>() + ")";
    std::snprintf(line, sizeof line, "%7u  %6zu  %-12s  %13.3f  %14.3f  %11.2f  %6.0f%%  %9.2f  %13.1f\n", r["strands"].get<unsigned>(),
                  r["chunks"].get<std::size_t>(), walk.c_str(), r["tessellate"]["ms"].get<double>(), interp["ms"].get<double>(),
                  resolved ? interp["gb_per_s"].get<double>() : 0.0,
                  resolved ? 100.0 * interp["fraction_of_copy"].get<double>() : 0.0,
                  r["copy"]["alone_gb_per_s"].get<double>(), r["frame_wall_ms"].get<double>());
    std::cout << line;
    if (!resolved)
      std::cout << "  no bandwidth derived (0 above): " << r["unresolved_because"].get<std::string>() << "\n";
  }
}

void run(BenchOptions& o) {
  hp::cli::applyGroomOptions(o.groomOptions, o.groom);
  if (o.frames == 0 || o.frames > 1000) throw hp::Error("bench strands: --frames must be in [1, 1000]");
  for (std::uint32_t s : o.strands)
    if (s == 0 || s > 4'000'000) throw hp::Error("bench strands: --strands values must be in [1, 4000000]");
  std::vector<hp::compute::InterpolateWalk> walks;
  for (const std::string& w : o.walks) {
    const auto walk = hp::compute::parseInterpolateWalk(w);
    if (!walk) throw hp::Error("bench strands: --walk values must be auto, strand or vertex, got '" + w + "'");
    walks.push_back(*walk);
  }
  auto ctx = hp::cli::createBenchContext(o.device, "bench strands");
  nlohmann::json report = {{"device", ctx->properties().deviceName}, {"frames", o.frames},
                           {"copy_bytes", kCopyBytes}, {"results", nlohmann::json::array()}};
  for (std::uint32_t s : o.strands)
    for (hp::compute::InterpolateWalk w : walks) report["results"].push_back(toJson(benchOne(*ctx, s, w, o)));
  if (o.json)
    std::cout << hp::jsonText(report) << "\n";
  else
    printText(report);
}

void setup(CLI::App& app) {
  auto o = std::make_shared<BenchOptions>();
  CLI::App* cmd = hp::cli::benchSuite(app, "strands", "Time the tessellate and interpolate passes on the device");
  cmd->add_option("--strands", o->strands, "Render strand counts, comma separated")->delimiter(',')->capture_default_str();
  cmd->add_option("--frames", o->frames, "Timed frames per count (median), after one warm-up")->capture_default_str();
  cmd->add_option("--vertices", o->vertices, "Vertices per strand (Q)")->capture_default_str();
  cmd->add_option("--walk", o->walks, "Interpolate walks, comma separated: auto, strand (one invocation per strand), vertex")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_flag("--json", o->json, "Print JSON");
  cmd->add_option("--device", o->device, "Vulkan device: index or name substring (env HAIRPIPE_DEVICE)");
  hp::cli::addGroomOptions(*cmd, o->groomOptions);
  cmd->callback([o] { run(*o); });
}
}  // namespace

HP_CLI_COMMAND(setup);
}  // namespace hp::cli::cmd_bench_strands
