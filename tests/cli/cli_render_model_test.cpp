// `hairpipe render --model FILE` (and `bench --model`) without a scene: the guesses (units, up axis, camera)
// are said on stderr and in --json, --units/--up override them, and a view with no hair in it is an error.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "engine/core/hair/hair_file.h"
#include "tests/hair/parted_crown.h"
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

// A parted model's bare scalp triangles are said on stderr and in --json where strands are blended from the
// guides; drawing the model's own strands leaves none bare, and says nothing.
TEST(CliRenderModel, BareScalpTrianglesAreReportedWhereStrandsAreBlended) {
  const auto model = freshTempPath("hairpipe_cli_parted.hair");
  hp::writeHairFile(model, hp::test::hairFileOf(hp::test::partedCrown(0.0f)));
  const auto png = freshTempPath("hairpipe_cli_parted.png");
  for (const char* density : {"--density", "--own-strands"}) {
    std::vector<std::string> args = {"render", "--model", model.string(), "--width", "32", "--height", "24", "--frames",
                                     "1", "--no-shadows", "--json", "--out", png.string(), density};
    if (std::string(density) == "--density") args.push_back("500");
    const auto r = runCli(args);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto guessed = nlohmann::json::parse(r.out)["guessed"];
    if (std::string(density) == "--density") {
      ASSERT_TRUE(guessed.contains("bare_scalp_triangles")) << r.out;
      EXPECT_GT(guessed["bare_scalp_triangles"].get<int>(), 0);
      EXPECT_NE(r.err.find("scalp triangles left bare"), std::string::npos) << r.err;
    } else {
      EXPECT_FALSE(guessed.contains("bare_scalp_triangles")) << r.out;
      EXPECT_EQ(r.err.find("left bare"), std::string::npos) << r.err;
    }
  }
}

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

// A model of at least 20,000 strands draws its own strands (one render strand on every guide: the dumped roots
// are the model's roots); a smaller one has 20,000 interpolated unless --own-strands asks for its own.
TEST(CliRenderModel, AModelWithManyStrandsDrawsItsOwnStrands) {
  for (const std::uint32_t strands : {20000u, 2000u}) {
    const auto model = freshTempPath("hairpipe_cli_model_many_" + std::to_string(strands) + ".hair");
    hp::HairFileData d;
    d.strandCount = strands;
    d.defaultSegments = 3;
    std::vector<glm::vec3> roots;
    for (std::uint32_t s = 0; s < strands; ++s) {
      const float a = 2.39996f * float(s), y = 1.0f - 0.6f * float(s) / float(strands), r = std::sqrt(1.0f - y * y);
      const glm::vec3 n(r * std::cos(a), y, r * std::sin(a));
      roots.push_back(0.09f * n);
      for (int k = 0; k < 4; ++k) d.points.push_back(0.09f * n + 0.03f * float(k) * glm::vec3(0.3f * n.x, -1.0f, 0.3f * n.z));
    }
    hp::writeHairFile(model, d);
    for (const bool own : {false, true}) {
      if (strands == 20000u && own) continue;
      const auto dump = freshTempPath("hairpipe_cli_model_many.hair.out.hair");
      std::vector<std::string> args{"render", "--model", model.string(), "--units", "m", "--width", "48", "--height", "36",
                                    "--frames", "1", "--no-shadows", "--out", freshTempPath("many.png").string(),
                                    "--dump-strands", dump.string()};
      if (own) args.push_back("--own-strands");
      const auto r = runCli(args);
      ASSERT_EQ(r.exitCode, 0) << r.err;
      const hp::HairFileData out = hp::readHairFile(dump);
      const bool ownStrands = strands == 20000u || own;
      EXPECT_EQ(out.strandCount, ownStrands ? strands : 20000u) << strands << (own ? " --own-strands" : "");
      if (!ownStrands) continue;
      // Every dumped root is a model root (a settling frame does not move roots).
      double worst = 0.0;
      std::uint32_t offset = 0;
      for (std::uint32_t s = 0; s < out.strandCount; offset += out.strandPointCount(s), s += 97) {
        double nearest = 1e30;
        for (const glm::vec3& root : roots) nearest = std::min(nearest, double(glm::distance(root, out.points[offset])));
        worst = std::max(worst, nearest);
        for (std::uint32_t k = s + 1; k < std::min(s + 97, out.strandCount); ++k) offset += out.strandPointCount(k);
      }
      EXPECT_LT(worst, 1e-5) << strands;
    }
  }
}

// `hairpipe bench --model FILE` times the frame of that model with its camera framed as render frames it:
// --strands interpolated on it, or with --own-strands the file's own strands (the report names the model and
// the count drawn); --own-strands with --strands, a file of another kind, and a report onto the model are
// refused before a frame runs.
TEST(CliBenchModel, BenchesAModelWithItsOwnOrInterpolatedStrands) {
  const auto model = centimetreZUpModel();
  const auto json = freshTempPath("hairpipe_cli_bench_model.json");
  for (const bool own : {true, false}) {
    std::vector<std::string> args{"bench", "--raster", "compute", "--model", model.string(), "--resolution", "48x36",
                                  "--frames", "1", "--groom", "none", "--json", json.string()};
    const std::vector<std::string> strands = own ? std::vector<std::string>{"--own-strands"}
                                                 : std::vector<std::string>{"--strands", "300"};
    args.insert(args.end(), strands.begin(), strands.end());
    const auto r = runCli(args);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("guessed units cm"), std::string::npos) << r.err;
    std::ifstream in(json);
    const nlohmann::json report = nlohmann::json::parse(in);
    ASSERT_EQ(report["results"].size(), 1u) << report.dump();
    const nlohmann::json& row = report["results"][0];
    EXPECT_EQ(row["model"], model.string());
    EXPECT_EQ(row["own_strands"], own);
    EXPECT_EQ(row["strands"], own ? 200u : 300u);
    EXPECT_GT(row["raster_entries"].get<double>(), 0.0) << "no hair in view";
    EXPECT_TRUE(row["passes"].contains("raster fine")) << row.dump();
  }
  // Refused with exit 1, no report written (the CLI11 exclusion, the file kind: before any frame runs).
  const auto refusedJson = freshTempPath("hairpipe_cli_bench_model_refused.json");
  expectRefused({"bench", "--raster", "compute", "--frames", "1", "--json", refusedJson.string()},
                {{{"--model", model.string(), "--own-strands", "--strands", "100"}, "excludes"},
                 {{"--model", freshTempPath("not_a_model.png").string()}, "expected 'default', a .hair, .tfx or .obj file"}},
                refusedJson);
  // A corrupt model is refused before any device is chosen (the device asked for does not exist).
  const auto corrupt = freshTempPath("hairpipe_cli_bench_corrupt.hair");
  std::ofstream(corrupt, std::ios::binary) << "HAIR";  // a header cut short
  expectRefused({"bench", "--raster", "compute", "--frames", "1", "--device", "99", "--json", refusedJson.string()},
                {{{"--model", corrupt.string()}, corrupt.string() + ": short header"}}, refusedJson);
  // The report may not overwrite the model it times.
  const auto before = std::filesystem::file_size(model);
  expectRefused({"bench", "--raster", "compute", "--frames", "1", "--model", model.string()},
                {{{"--json", model.string()}, "--json"}, {{"--plot", model.string()}, "--plot"}});
  EXPECT_EQ(std::filesystem::file_size(model), before);
}
