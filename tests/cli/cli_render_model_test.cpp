// `hairpipe render --model FILE` without a scene: the guesses (units, up axis, camera) are said on
// stderr and in --json, --units/--up override them, and a view with no hair in it is an error.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "engine/core/hair/hair_file.h"
#include "tests/support/cli_runner.h"

using hp::test::expectRefused;
using hp::test::freshTempPath;
using hp::test::runCli;

namespace {
// 200 strands on the top of a 9 cm head, in centimetres, Z up, hanging down 25 cm.
std::filesystem::path centimetreZUpModel() {
  const auto path = freshTempPath("hairpipe_cli_model_cm_z.hair");
  hp::HairFileData d;
  d.strandCount = 200;
  d.defaultSegments = 4;
  for (std::uint32_t s = 0; s < d.strandCount; ++s) {
    const float a = 0.7f * float(s), z = 1.0f - float(s) / float(d.strandCount), r = std::sqrt(1.0f - z * z);
    const glm::vec3 root(9.0f * r * std::cos(a), 9.0f * r * std::sin(a), 9.0f * z);
    for (int k = 0; k < 5; ++k) d.points.push_back(root + glm::vec3(0.0f, 0.0f, -6.0f * float(k)));
  }
  hp::writeHairFile(path, d);
  return path;
}
}  // namespace

TEST(CliRenderModel, GuessesAreReportedOnStderrAndInJson) {
  const auto model = centimetreZUpModel();
  const auto png = freshTempPath("hairpipe_cli_model.png");
  auto r = runCli({"render", "--model", model.string(), "--width", "96", "--height", "72", "--density", "1000",
                   "--frames", "2", "--no-shadows", "--json", "--out", png.string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("guessed units cm"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("up z"), std::string::npos) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j.contains("guessed")) << r.out;
  EXPECT_NE(j["guessed"]["model"].get<std::string>().find("units cm"), std::string::npos);
  EXPECT_GT(j["guessed"]["camera"]["distance"].get<double>(), 0.1);
  EXPECT_TRUE(std::filesystem::exists(png));
  // Overrides are taken as given and said so.
  r = runCli({"render", "--model", model.string(), "--units", "mm", "--up", "y", "--width", "64", "--height", "48",
              "--density", "500", "--frames", "1", "--no-shadows", "--out", png.string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("units mm (given), up y (given)"), std::string::npos) << r.err;
}

TEST(CliRenderModel, AViewWithoutHairIsAnErrorAndWritesNothing) {
  const auto model = centimetreZUpModel();
  const auto scene = freshTempPath("hairpipe_cli_model_away.json");
  {
    std::ofstream(scene) << R"({"model": {"source": ")" << model.filename().string()
                         << R"(", "scale": 0.01, "up": "z"}, "camera": {"target": [5, 0, 0], "distance": 0.5}})";
  }
  const auto png = freshTempPath("hairpipe_cli_model_away.png");
  expectRefused({"render", "--width", "64", "--height", "48", "--frames", "1", "--out", png.string()},
                {{{"--scene", scene.string()}, "no hair is visible"},
                 {{"--model", model.string(), "--units", "inch"}, "units must be m, cm or mm"},
                 {{"--model", model.string(), "--up", "x"}, "up"},
                 {{"--units", "cm"}, "--units/--up apply to a --model file"}},
                png);
}
