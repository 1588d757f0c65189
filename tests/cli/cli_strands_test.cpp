// `hairpipe strands`: writes a readable .hair with the expected counts (render strands, guides only,
// from a .hair model), and refuses bad options with exit code 1 and a message naming the option.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/core/hair/hair_file.h"
#include "tests/support/cli_runner.h"

using hp::test::runCli;
namespace fs = std::filesystem;

namespace {
fs::path tempPath(const std::string& name) {
  fs::path dir = fs::path(::testing::TempDir()) / "hairpipe_cli_strands";
  fs::create_directories(dir);
  fs::path p = dir / name;
  fs::remove(p);
  return p;
}

void expectUniformFiniteStrands(const hp::HairFileData& hair, std::uint32_t strands, std::uint32_t vertices) {
  EXPECT_EQ(hair.strandCount, strands);
  ASSERT_EQ(hair.pointCount(), std::uint64_t(strands) * vertices);
  for (std::uint32_t s = 0; s < hair.strandCount; ++s) ASSERT_EQ(hair.strandPointCount(s), vertices);
  for (const glm::vec3& p : hair.points) ASSERT_TRUE(std::isfinite(p.x + p.y + p.z));
}
}  // namespace

TEST(CliStrands, WritesRenderStrandsOfTheRequestedDensity) {
  fs::path out = tempPath("strands.hair");
  auto r = runCli({"strands", "--density", "5000", "--out", out.string(), "--json", "--validation"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["strands"].get<std::uint32_t>(), 5000u);
  EXPECT_EQ(j["vertices_per_strand"].get<std::uint32_t>(), 36u);
  EXPECT_EQ(j["points"].get<std::uint32_t>(), 5000u * 36);
  EXPECT_FALSE(j["guides_only"].get<bool>());
  expectUniformFiniteStrands(hp::readHairFile(out), 5000, 36);
}

TEST(CliStrands, GuidesOnlyWritesOneSmoothedStrandPerGuide) {
  fs::path out = tempPath("guides.hair");
  auto r = runCli({"strands", "--guides-only", "--vertices", "12", "--out", out.string(), "--json"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  const auto guides = j["guides"].get<std::uint32_t>();
  EXPECT_GT(guides, 500u);
  EXPECT_EQ(j["strands"].get<std::uint32_t>(), guides);
  expectUniformFiniteStrands(hp::readHairFile(out), guides, 12);
}

TEST(CliStrands, ReadsAHairModelAndPrintsASummary) {
  fs::path model = tempPath("model.hair"), out = tempPath("from_model.hair");
  ASSERT_EQ(runCli({"strands", "--guides-only", "--out", model.string()}).exitCode, 0);
  auto r = runCli({"strands", "--model", model.string(), "--density", "2000", "--out", out.string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("2000 render strands x 36 vertices"), std::string::npos) << r.out;
  expectUniformFiniteStrands(hp::readHairFile(out), 2000, 36);
}

TEST(CliStrands, BadOptionsExitOneNamingTheOption) {
  fs::path out = tempPath("never.hair");
  hp::test::expectRefused({"strands", "--out", out.string()}, {
      {{"--density", "0"}, "--density"},
      {{"--density", "50000000"}, "--density"},
      {{"--density", "-1"}, "--density"},  // was the "scene's own" sentinel, so it ran with the default
      {{"--vertices", "5"}, "--vertices"},    // fewer than the 7 particles per guide
      {{"--vertices", "300"}, "--vertices"},  // more than 256
      {{"--model", "head.txt"}, "--model"},
  }, out);
}

TEST(CliStrands, OutIsRequired) {
  auto r = runCli({"strands"});
  EXPECT_NE(r.exitCode, 0);
  EXPECT_NE(r.err.find("--out"), std::string::npos) << r.err;
}

// The scene's groom is the default (the same strands as its values given as options), --no-groom the plain
// blend of the guides (the same strands as zero clumps, curl and frizz), and --clump/--curl/--frizz apply on top.
TEST(CliStrands, TheScenesGroomIsTheDefaultAndNoGroomThePlainBlend) {
  const auto strands = [](const std::string& name, std::vector<std::string> options) {
    const fs::path out = tempPath(name);
    std::vector<std::string> args = {"strands", "--density", "2000", "--out", out.string()};
    args.insert(args.end(), options.begin(), options.end());
    const auto r = runCli(args);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    return hp::readHairFile(out).points;
  };
  const auto groomed = strands("groom_default.hair", {});
  const auto explicitGroom = strands("groom_explicit.hair", {"--clump", "4,0.4,1.5", "--curl", "0.004,5,0.5", "--frizz",
                                                             "0.0008,40,4,0.02"});
  const auto plain = strands("groom_none.hair", {"--no-groom"});
  const auto zeros = strands("groom_zeros.hair", {"--clump", "0,0", "--curl", "0,0", "--frizz", "0"});
  const auto curlOnly = strands("groom_curl.hair", {"--no-groom", "--curl", "0.004,5"});
  ASSERT_EQ(groomed.size(), 2000u * 36);
  EXPECT_EQ(groomed, explicitGroom);
  EXPECT_EQ(plain, zeros);
  EXPECT_NE(groomed, plain);
  EXPECT_NE(curlOnly, plain);
  EXPECT_NE(curlOnly, groomed);
}
