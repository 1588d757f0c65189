// The info, devices and bench commands' front ends.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/core/build_identity.h"
#include "tests/support/cli_runner.h"

using hp::test::runCli;

TEST(CliInfo, ListsDevicesSelectionAndValidationLayerAsJson) {
  auto r = runCli({"info", "--json"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  ASSERT_FALSE(j["devices"].empty());
  EXPECT_TRUE(j["validation_layer"].get<bool>());
  const auto& d = j["devices"][j["selected"].get<int>()];
  EXPECT_FALSE(d["name"].get<std::string>().empty());
  EXPECT_GT(d["max_storage_buffer_range"].get<std::uint64_t>(), 0u);
  EXPECT_GT(d["max_compute_workgroup_invocations"].get<std::uint32_t>(), 0u);
  EXPECT_GT(d["timestamp_period_ns"].get<double>(), 0.0);
  EXPECT_TRUE(d["suitable"].get<bool>());
  // The tool's build and the disk cache it uses: HAIRPIPE_CACHE_DIR, which CTest sets for every test.
  EXPECT_EQ(j["build_identity"], hp::buildIdentity());
  const char* folder = std::getenv("HAIRPIPE_CACHE_DIR");
  if (folder && *folder) EXPECT_EQ(j["disk_cache"], folder);
  else EXPECT_TRUE(j["disk_cache"].is_null());
}

TEST(CliInfo, TextOutputMarksTheSelectedDevice) {
  auto r = runCli({"info"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("<- selected"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("maxStorageBufferRange"), std::string::npos);
}

TEST(CliInfo, UnknownDeviceExitsNonZeroAndListsDevices) {
  auto r = runCli({"info", "--device", "nosuchdevice"});
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("nosuchdevice"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("available devices"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("[0]"), std::string::npos) << r.err;
}

TEST(CliHelp, EverySubcommandHasHelp) {
  auto r = runCli({"--help"});
  EXPECT_EQ(r.exitCode, 0);
  EXPECT_NE(r.out.find("info"), std::string::npos);
  auto info = runCli({"info", "--help"});
  EXPECT_EQ(info.exitCode, 0);
  EXPECT_NE(info.out.find("--device"), std::string::npos);
  EXPECT_NE(info.out.find("--json"), std::string::npos);
}

TEST(CliUsage, UsageErrorsExitWithCodeOneAndHelpSucceeds) {
  EXPECT_EQ(runCli({"nosuchcommand"}).exitCode, 1);
  EXPECT_EQ(runCli({"info", "--no-such-flag"}).exitCode, 1);
  auto r = runCli({"lut", "--mode", "bogus", "--out", "/tmp/hairpipe-never"});
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("bogus"), std::string::npos) << r.err;
  const auto version = runCli({"--version"});
  EXPECT_EQ(version.exitCode, 0);
  EXPECT_NE(version.out.find("hairpipe 0.2.0"), std::string::npos) << version.out;  // the public header's
  // Option conversion errors come in the tool's one format.
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"render", "--width", "-1"}, {"reference", "--spp", "4294967296"}}) {
    const auto bad = runCli(args);
    EXPECT_EQ(bad.exitCode, 1);
    EXPECT_EQ(bad.err.rfind("hairpipe: error: Could not convert: " + args[1], 0), 0u) << bad.err;
  }
}

// The benchmark suites are subcommands of `bench`: each has its help, a suite runs alone
// (the whole-frame bench does not run as well) and the former `bench-*` names are gone.
TEST(CliBench, SuitesAreSubcommandsOfBench) {
  auto r = runCli({"bench", "--help"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  for (const char* suite : {"sim", "strands", "opacity", "instances", "head", "assets"}) {
    EXPECT_NE(r.out.find(suite), std::string::npos) << suite;
    EXPECT_EQ(runCli({"bench", suite, "--help"}).exitCode, 0) << suite;
  }
  auto old = runCli({"bench-sim", "--frames", "1"});  // not a command: nothing runs
  EXPECT_EQ(old.exitCode, 1);
  EXPECT_NE(old.err.find("A subcommand is required"), std::string::npos) << old.err;
  // An option of the frame bench before a suite's name would be ignored by the suite: refused.
  auto misplaced = runCli({"bench", "--strands", "200", "assets", "--repeat", "1"});
  EXPECT_EQ(misplaced.exitCode, 1);
  EXPECT_NE(misplaced.err.find("bench assets: --strands before the suite name"), std::string::npos) << misplaced.err;
  EXPECT_EQ(misplaced.out.find("read"), std::string::npos) << "the suite ran: " << misplaced.out;
  auto assets = runCli({"bench", "assets", "--strands", "200", "--points", "2000", "--repeat", "1", "--json"});
  ASSERT_EQ(assets.exitCode, 0) << assets.err;
  nlohmann::json parsed;
  EXPECT_NO_THROW(parsed = nlohmann::json::parse(assets.out)) << assets.out;
  EXPECT_TRUE(parsed.is_object()) << assets.out;
  EXPECT_EQ(assets.out.find("median of"), std::string::npos) << "the frame bench ran too";
  // A model too large to build is refused by name before any allocation (it was a bare std::bad_alloc).
  auto huge = runCli({"bench", "assets", "--strands", "1000000", "--points", "2000000000", "--repeat", "1"});
  EXPECT_EQ(huge.exitCode, 1);
  EXPECT_NE(huge.err.find("bench assets: --points must be at most"), std::string::npos) << huge.err;
}

// `bench strands` and `bench sim` time their copy yardstick alone too, and derive bandwidth only where the
// device's timestamps resolve the passes (the same rule as the frame bench's).
TEST(CliBench, StrandAndSimSuitesDeriveBandwidthOnlyWhereTimestampsResolve) {
  auto strands = runCli({"bench", "strands", "--strands", "1000", "--frames", "1", "--walk", "strand,vertex", "--no-groom",
                         "--json"});
  ASSERT_EQ(strands.exitCode, 0) << strands.err;
  const auto strandRows = nlohmann::json::parse(strands.out)["results"];
  ASSERT_EQ(strandRows.size(), 2u) << "one row per walk";
  EXPECT_FALSE(strandRows[0]["per_vertex"].get<bool>());
  EXPECT_TRUE(strandRows[1]["per_vertex"].get<bool>());
  // The scenes' groom (the suite's default) carries a frame along each strand: asked per vertex, it walks per
  // strand with its stores staged (per vertex: lavapipe's shared memory holds the blocks); per strand as asked.
  auto groomed = runCli({"bench", "strands", "--strands", "1000", "--frames", "1", "--walk", "vertex,strand", "--json"});
  ASSERT_EQ(groomed.exitCode, 0) << groomed.err;
  const auto groomedRows = nlohmann::json::parse(groomed.out)["results"];
  ASSERT_EQ(groomedRows.size(), 2u);
  EXPECT_TRUE(groomedRows[0]["per_vertex"].get<bool>());
  EXPECT_EQ(groomedRows[0]["walk_taken"].get<std::string>(), "staged");
  EXPECT_FALSE(groomedRows[1]["per_vertex"].get<bool>());
  EXPECT_EQ(groomedRows[1]["walk_taken"].get<std::string>(), "strand");
  EXPECT_EQ(strandRows[1]["walk_taken"].get<std::string>(), "vertex");
  for (const auto& row : strandRows) {
    EXPECT_GE(row["copy"]["alone_runs"].get<unsigned>(), 5u);
    // The yardstick is the faster of the transfer copy and the shader's copy, both timed alone.
    const double transfer = row["copy"]["transfer_gb_per_s"].get<double>();
    const double compute = row["copy"]["compute_gb_per_s"].get<double>();
    EXPECT_GT(transfer, 0.0);
    EXPECT_GT(compute, 0.0);
    EXPECT_DOUBLE_EQ(row["copy"]["alone_gb_per_s"].get<double>(), std::max(transfer, compute));
    const bool resolved = row["timestamps_resolve_passes"].get<bool>();
    EXPECT_EQ(row["interpolate"].contains("fraction_of_copy"), resolved);
    EXPECT_EQ(row["unresolved_because"].get<std::string>().empty(), resolved);
  }
  auto walk = runCli({"bench", "strands", "--walk", "warp"});
  EXPECT_EQ(walk.exitCode, 1);
  EXPECT_NE(walk.err.find("--walk values must be auto, strand or vertex, got 'warp'"), std::string::npos) << walk.err;
  auto sim = runCli({"bench", "sim", "--guides", "100", "--frames", "1", "--json"});
  ASSERT_EQ(sim.exitCode, 0) << sim.err;
  const auto simRows = nlohmann::json::parse(sim.out)["results"];
  ASSERT_EQ(simRows.size(), 2u) << "the hair grid off and on (--grid both, the default)";
  for (const auto& row : simRows) {
    const bool resolved = row["timestamps_resolve_passes"].get<bool>();
    EXPECT_EQ(row.contains("fraction_of_copy"), resolved);
    EXPECT_GT(row["copy_gb_per_s"].get<double>(), 0.0);
    EXPECT_EQ(row["grid_ms"].is_null(), !row["grid"].get<bool>()) << "the grid's passes are timed where it acts";
  }
  EXPECT_FALSE(simRows[0]["grid"].get<bool>());
  EXPECT_GT(simRows[1]["grid_ms"].get<double>(), 0.0);
}

// `bench sim --grid` takes on, off or both; anything else is refused by name before the device is opened.
TEST(CliBench, SimRefusesABadGridChoice) {
  auto r = runCli({"bench", "sim", "--guides", "100", "--frames", "1", "--grid", "sideways"});
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("--grid must be on, off or both, got 'sideways'"), std::string::npos) << r.err;
  EXPECT_EQ(r.out.find("simulation on"), std::string::npos) << "a benchmark ran: " << r.out;
}

namespace {
// A bench command refused before a frame runs: exit status 1, `message` in its error output, no frame reported.
void expectBenchRefused(const std::vector<std::string>& args, const std::string& message) {
  const auto r = runCli(args);
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find(message), std::string::npos) << r.err;
  EXPECT_EQ(r.out.find("median of"), std::string::npos) << "a frame ran: " << r.out;
}
}  // namespace

// `bench --skin-bounce` and `--skin-indirect` take off and/or on, `--bounce-samples` values in [2, 256];
// anything else is refused by name before a frame runs.
TEST(CliBench, RefusesBadSkinBounceAndBounceSampleValues) {
  expectBenchRefused({"bench", "--raster", "compute", "--skin-bounce", "off,maybe", "--frames", "1"},
                     "bench: --skin-bounce takes off and/or on, got 'maybe'");
  expectBenchRefused({"bench", "--skin-indirect", "on,sometimes", "--frames", "1"},
                     "bench: --skin-indirect takes off and/or on, got 'sometimes'");
  expectBenchRefused({"bench", "--raster", "compute", "--bounce-samples", "8,1", "--frames", "1"},
                     "bench: --bounce-samples values must be in [2, 256], got 1");
}

// `bench --msaa` values are sample counts a render target takes, `--resolution` two sides in [1, 16384], and
// `--lod-fraction` values in LodSettings.minFraction's range: refused by name before a model is built (a side
// past 2^32 wrapped around to a small one, and a frame ran).
TEST(CliBench, RefusesBadMsaaResolutionAndLodFractionValues) {
  expectBenchRefused({"bench", "--raster", "compute", "--msaa", "4,3", "--frames", "1"},
                     "bench: --msaa values must be 1, 2, 4 or 8, got 3");
  expectBenchRefused({"bench", "--raster", "compute", "--lod-fraction", "0.5,0.0001", "--frames", "1"},
                     "bench: --lod-fraction values must be in [0.001, 1], got 0.0001");
  for (const char* size : {"4294967328x4294967320", "-5x24", "32x24x", "32x0", "x24", "32 x24"}) {
    SCOPED_TRACE(size);
    expectBenchRefused({"bench", "--raster", "compute", "--resolution", size, "--frames", "1", "--strands", "100"},
                       "--resolution must be WxH with each in [1, 16384]");
  }
}

namespace {
// `hairpipe bench` of the compute path at 100 strands, 32x24, one frame, with `extra` options: its JSON report
// (null when the run failed, which is then a test failure).
nlohmann::json tinyComputeBench(std::vector<std::string> extra, const std::string& file) {
  const std::string json = ::testing::TempDir() + file;
  std::vector<std::string> args = {"bench", "--raster", "compute", "--strands", "100", "--resolution", "32x24",
                                   "--frames", "1", "--json", json};
  args.insert(args.end(), extra.begin(), extra.end());
  const auto run = runCli(args);
  EXPECT_EQ(run.exitCode, 0) << run.err;
  if (run.exitCode != 0) return nullptr;
  std::ifstream in(json);
  return nlohmann::json::parse(in);
}
}  // namespace

// `bench --fine-walk` takes auto, direct and/or staged (refused by name before a frame runs); each walk is a
// case of its own, named in the report.
TEST(CliBench, FineWalkListIsCheckedThenBenched) {
  expectBenchRefused({"bench", "--raster", "compute", "--fine-walk", "staged,sideways", "--frames", "1"},
                     "bench: --fine-walk takes auto, direct and/or staged, got 'sideways'");
  const nlohmann::json report =
      tinyComputeBench({"--fine-walk", "direct,staged,auto"}, "bench_fine_walks.json");
  ASSERT_FALSE(report.is_null());
  std::vector<std::string> names, walks, run;
  for (const auto& row : report["results"]) {
    names.push_back(row["raster"].get<std::string>());
    walks.push_back(row["fine_walk"].get<std::string>());
    run.push_back(row["fine_walk_run"].get<std::string>());
    EXPECT_TRUE(row["passes"].contains("raster fine")) << row.dump();
  }
  EXPECT_EQ(names, (std::vector<std::string>{"compute, direct fine walk", "compute, staged fine walk", "compute"}));
  EXPECT_EQ(walks, (std::vector<std::string>{"direct", "staged", "auto"}));
  // The walk that ran: the one asked for, and Auto resolved (lavapipe, a CPU device whose texel views fit: direct).
  EXPECT_EQ(run, (std::vector<std::string>{"direct", "staged", "direct"}));
}

// `bench --grow-lists` takes off and/or on (refused by name before a frame runs); each is a case of its own,
// and the grown lists' raster target holds less device memory than the close-up reserve's.
TEST(CliBench, GrowListsIsCheckedThenBenched) {
  expectBenchRefused({"bench", "--raster", "compute", "--grow-lists", "maybe", "--frames", "1"},
                     "bench: --grow-lists takes off and/or on, got 'maybe'");
  const nlohmann::json report = tinyComputeBench({"--grow-lists", "off,on"}, "bench_grow_lists.json");
  ASSERT_FALSE(report.is_null());
  ASSERT_EQ(report["results"].size(), 2u);
  const nlohmann::json &reserved = report["results"][0], &grown = report["results"][1];
  EXPECT_FALSE(reserved["grow_lists"].get<bool>());
  EXPECT_TRUE(grown["grow_lists"].get<bool>());
  EXPECT_EQ(reserved["raster"], "compute");
  EXPECT_EQ(grown["raster"], "compute, grown lists");
  EXPECT_LT(grown["raster_target_mib"].get<double>(), reserved["raster_target_mib"].get<double>());
  EXPECT_EQ(grown["raster_overflow"].get<std::uint64_t>(), 0u);
}

// `bench --shading-spacing` takes pixels in [0, 4096] (refused by name before a frame runs); each spacing is a
// case of its own, and the report says how many vertices its frame shaded: fewer where pairs share them.
TEST(CliBench, ShadingSpacingListIsCheckedThenBenched) {
  expectBenchRefused({"bench", "--raster", "compute", "--shading-spacing", "8,-1", "--frames", "1"},
                     "bench: --shading-spacing values must be in [0, 4096] pixels");
  const nlohmann::json report = tinyComputeBench({"--shading-spacing", "0,24"}, "bench_shading_spacing.json");
  ASSERT_FALSE(report.is_null());
  ASSERT_EQ(report["results"].size(), 2u);
  const nlohmann::json &every = report["results"][0], &spaced = report["results"][1];
  EXPECT_EQ(every["shading_spacing"].get<double>(), 0.0);
  EXPECT_EQ(spaced["shading_spacing"].get<double>(), 24.0);
  EXPECT_EQ(every["raster"], "compute, shading spacing 0");
  EXPECT_EQ(spaced["raster"], "compute");
  EXPECT_GT(every["shaded_vertices"].get<double>(), 0.0);
  EXPECT_LT(spaced["shaded_vertices"].get<double>(), every["shaded_vertices"].get<double>());
}

// `bench --groom` takes scene and/or none (refused by name before a frame runs); each is a case of its own.
TEST(CliBench, GroomListIsCheckedThenBenched) {
  expectBenchRefused({"bench", "--raster", "compute", "--groom", "scene,curly", "--frames", "1"},
                     "bench: --groom takes scene and/or none, got 'curly'");
  const nlohmann::json report = tinyComputeBench({"--groom", "scene,none"}, "bench_grooms.json");
  ASSERT_FALSE(report.is_null());
  std::vector<std::string> names, grooms;
  for (const auto& row : report["results"]) {
    names.push_back(row["raster"].get<std::string>());
    grooms.push_back(row["groom"].get<std::string>());
  }
  EXPECT_EQ(names, (std::vector<std::string>{"compute", "compute, no groom"}));
  EXPECT_EQ(grooms, (std::vector<std::string>{"scene", "none"}));
}

// `bench --scattering` and `--lut-mode` are refused by name before a frame runs; dual with a model other than
// the physical one (which has no dual tables) is benchmarked as single scattering, once.
TEST(CliBench, ScatteringAndLutModeListsAreCheckedThenCombined) {
  expectBenchRefused({"bench", "--raster", "compute", "--scattering", "dual,triple", "--frames", "1"},
                     "bench: --scattering: scattering must be single or dual, got 'triple'");
  expectBenchRefused({"bench", "--raster", "compute", "--lut-mode", "physical,glossy", "--frames", "1"},
                     "bench: --lut-mode: unknown LUT mode 'glossy'");
  const nlohmann::json report =
      tinyComputeBench({"--lut-mode", "float,physical", "--scattering", "single,dual"}, "bench_shadings.json");
  ASSERT_FALSE(report.is_null());
  std::vector<std::string> names, scatterings;
  for (const auto& row : report["results"]) {
    names.push_back(row["raster"].get<std::string>());
    scatterings.push_back(row["scattering"].get<std::string>());
    // The yardstick copy ran in submissions of its own; bandwidth only where the timestamps resolve passes.
    EXPECT_GE(row["copy_runs"].get<unsigned>(), 5u);
    EXPECT_GT(row["copy_gb_per_s"].get<double>(), 0.0);
    const bool resolved = row["timestamps_resolve_passes"].get<bool>();
    for (const auto& [name, pass] : row["passes"].items())
      EXPECT_EQ(pass.contains("fraction_of_copy"), resolved && pass.contains("bytes")) << name;
  }
  EXPECT_EQ(names, (std::vector<std::string>{"compute, float", "compute, single scattering", "compute"}));
  EXPECT_EQ(scatterings, (std::vector<std::string>{"single", "single", "dual"}));
}

// Every material option reaches the frame bench's fibres, the per-strand variations included (they once fell
// back to the scene's material when given alone).
TEST(CliBench, AVariationGivenAloneReachesTheFibres) {
  const nlohmann::json report = tinyComputeBench({"--roughness-variation", "0"}, "bench_roughness_variation.json");
  ASSERT_FALSE(report.is_null());
  ASSERT_EQ(report["results"].size(), 1u);
  EXPECT_EQ(report["results"][0]["roughness_variation"].get<double>(), 0.0);
}
