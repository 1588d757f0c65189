#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>

#include "engine/core/hair/hair_file.h"
#include "tests/support/cli_runner.h"

using hp::test::expectRefused;
using hp::test::runCli;

TEST(CliSimulate, ReportsTheSettledStateAsJsonAndWritesTheGuides) {
  const auto out = std::filesystem::temp_directory_path() / "hairpipe_cli_simulate.hair";
  std::filesystem::remove(out);
  auto r = runCli({"simulate", "--frames", "40", "--animate", "nod", "--json", "--validation", "--out", out.string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["frames"], 40);
  EXPECT_EQ(j["animation"], "nod");
  EXPECT_GT(j["guides"].get<int>(), 1000);
  EXPECT_EQ(j["nan_count"], 0);
  EXPECT_LT(j["max_length_error"].get<double>(), 0.01);
  EXPECT_GE(j["min_collider_clearance"].get<double>(), -1e-5);
  EXPECT_GT(j["max_speed"].get<double>(), 0.0);
  EXPECT_GT(j["gpu_ms_per_frame_median"].get<double>(), 0.0);
  // The default head has a distance field: the guide middles stand off it, by 3 cm on average at rest.
  ASSERT_TRUE(j["layer_thickness"].is_object()) << r.out;
  EXPECT_EQ(j["layer_thickness"]["guides"], j["guides"]);
  EXPECT_GT(j["layer_thickness"]["mean"].get<double>(), 0.005);
  EXPECT_LT(j["layer_thickness"]["mean"].get<double>(), 0.2);
  EXPECT_GE(j["layer_thickness"]["p90"].get<double>(), j["layer_thickness"]["mean"].get<double>());
  hp::HairFileData guides = hp::readHairFile(out);
  EXPECT_EQ(guides.strandPointCount(0), j["particles_per_guide"].get<std::uint32_t>());
  EXPECT_EQ(guides.pointCount(), j["guides"].get<std::uint32_t>() * j["particles_per_guide"].get<std::uint32_t>());
  std::filesystem::remove(out);
}

TEST(CliSimulate, BadParametersExitWithAMessageNamingThem) {
  expectRefused({"simulate"}, {
      {{"--dt", "0"}, "dt"},           {{"--dt", "nan"}, "dt"},
      {{"--dt", "-0.1"}, "dt"},        {{"--iterations", "0"}, "iterations"},
      {{"--iterations", "1001"}, "iterations"}, {{"--substeps", "0"}, "substeps"},
      {{"--frames", "0"}, "frames"},   {{"--animate", "wobble"}, "wobble"},
      {{"--model", "missing.hair"}, "missing.hair"},
      {{"--volume", "-1"}, "volume"},  {{"--volume", "nan"}, "volume"},
      {{"--friction", "2"}, "friction"}, {{"--volume-target", "0"}, "volumeTarget"},
      {{"--grid-resolution", "200"}, "gridResolution"},
  });
}

// The hair grid's report: off by default (no peak or timing), and where it acts its peak density (above the
// target where the pinned roots crowd), its GPU time and the interaction measures.
TEST(CliSimulate, ReportsTheHairGridWhereItActs) {
  auto off = runCli({"simulate", "--frames", "4", "--json"});
  ASSERT_EQ(off.exitCode, 0) << off.err;
  auto j = nlohmann::json::parse(off.out);
  EXPECT_FALSE(j["grid"]["acts"].get<bool>());
  EXPECT_FALSE(j["grid"].contains("peak_density"));
  ASSERT_TRUE(j["interaction"].is_object());
  auto on = runCli({"simulate", "--frames", "4", "--volume", "0.6", "--friction", "0.1", "--grid-resolution", "16",
                    "--json", "--validation"});
  ASSERT_EQ(on.exitCode, 0) << on.err;
  j = nlohmann::json::parse(on.out);
  EXPECT_TRUE(j["grid"]["acts"].get<bool>());
  EXPECT_EQ(j["grid"]["cells"].size(), 3u);
  EXPECT_LE(j["grid"]["cells"][0].get<int>(), 16);
  EXPECT_GT(j["grid"]["peak_density"].get<double>(), j["grid"]["volume_target"].get<double>());
  EXPECT_GT(j["grid"]["gpu_ms_per_frame_median"].get<double>(), 0.0);
  EXPECT_GE(j["interaction"]["close_neighbour_fraction"].get<double>(), 0.0);
}

TEST(CliSimulate, AFailedRunLeavesNoOutputFile) {
  const auto out = std::filesystem::temp_directory_path() / "hairpipe_cli_simulate_fail.hair";
  std::filesystem::remove(out);
  auto r = runCli({"simulate", "--iterations", "0", "--out", out.string()});
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_FALSE(std::filesystem::exists(out));
}
