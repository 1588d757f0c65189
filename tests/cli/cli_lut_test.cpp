// `hairpipe lut`: the PFM/PNG/JSON files of both LUT modes (sizes, headers, texel values against the CPU
// build), material options reaching lut.json, and bad options (exit non-zero with a message, no files).
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>

#include "engine/core/shading/lut.h"
#include "tests/hair/hair_test_util.h"
#include "tests/support/cli_runner.h"

using hp::test::runCli;
using hp::test::slurp;
using hp::test::filesIn;
using hp::test::TempDir;

namespace {
// PFM: "PF" (rgb) or "Pf" (grey), "W H", "-1.0" (little-endian), then rows bottom (v = 0) first.
struct Pfm {
  std::string kind;
  std::uint32_t width = 0, height = 0;
  std::vector<float> values;
};
Pfm readPfm(const std::filesystem::path& p) {
  std::string bytes = slurp(p);
  std::istringstream in(bytes);
  Pfm pfm;
  std::string scale;
  in >> pfm.kind >> pfm.width >> pfm.height >> scale;
  in.get();  // the single whitespace after the header
  EXPECT_EQ(scale, "-1.0");
  const std::size_t count = std::size_t(pfm.width) * pfm.height * (pfm.kind == "PF" ? 3 : 1);
  const std::size_t offset = std::size_t(in.tellg());
  EXPECT_EQ(bytes.size(), offset + count * 4) << p;
  pfm.values.resize(count);
  if (bytes.size() == offset + count * 4) std::memcpy(pfm.values.data(), bytes.data() + offset, count * 4);
  return pfm;
}

bool isPng(const std::filesystem::path& p) { return slurp(p).rfind("\x89PNG\r\n\x1a\n", 0) == 0; }

TEST(CliLut, PaperModeWritesPfmPngAndJsonMatchingTheCpuBuild) {
  TempDir dir;
  auto r = runCli({"lut", "--out", (dir / "paper").string(), "--mode", "paper"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("wrote 2 paper textures"), std::string::npos) << r.out;
  EXPECT_EQ(filesIn(dir / "paper"), 2u * 4u + 1u);
  const hp::MarschnerLut lut = hp::buildLut(hp::LutMode::Paper, hp::HairMaterial{});
  for (const hp::LutTexture& t : lut.textures) {
    const auto base = dir / "paper" / t.name;
    Pfm rgb = readPfm(base.string() + "_rgb.pfm"), a = readPfm(base.string() + "_a.pfm");
    EXPECT_EQ(rgb.kind, "PF");
    EXPECT_EQ(a.kind, "Pf");
    EXPECT_EQ(rgb.width, 128u);
    EXPECT_EQ(rgb.height, 128u);
    ASSERT_EQ(rgb.values.size(), 128u * 128u * 3u);
    ASSERT_EQ(a.values.size(), 128u * 128u);
    std::size_t mismatches = 0;
    for (std::size_t px = 0; px < 128u * 128u; ++px) {
      for (int c = 0; c < 3; ++c) mismatches += rgb.values[px * 3 + c] != t.data[px * 4 + c];
      mismatches += a.values[px] != t.data[px * 4 + 3];
    }
    EXPECT_EQ(mismatches, 0u) << t.name;
    EXPECT_TRUE(isPng(base.string() + ".png"));
    EXPECT_TRUE(isPng(base.string() + "_a.png"));
  }
  auto j = nlohmann::json::parse(slurp(dir / "paper" / "lut.json"));
  EXPECT_EQ(j["mode"], "paper");
  ASSERT_EQ(j["textures"].size(), 2u);
  EXPECT_EQ(j["textures"][0]["format"], "R8G8B8A8_UNORM");
  EXPECT_EQ(j["textures"][1]["name"], "N");
  EXPECT_EQ(j["files"]["M"].size(), 4u);
  EXPECT_FLOAT_EQ(j["textures"][0]["scale"][0].get<float>(), lut.textures[0].scale[0]);
}

TEST(CliLut, FloatModeIsTheDefaultAndWritesThreeTextures) {
  TempDir dir;
  auto r = runCli({"lut", "--out", (dir / "float").string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(filesIn(dir / "float"), 3u * 4u + 1u);
  Pfm m = readPfm(dir / "float" / "M_rgb.pfm");
  EXPECT_EQ(m.width, 2048u);
  EXPECT_EQ(m.height, 1u);
  Pfm n1 = readPfm(dir / "float" / "N1_rgb.pfm");
  EXPECT_EQ(n1.width, 256u);
  EXPECT_EQ(n1.height, 128u);
  auto j = nlohmann::json::parse(slurp(dir / "float" / "lut.json"));
  EXPECT_EQ(j["mode"], "float");
  EXPECT_EQ(j["textures"][2]["format"], "R16G16B16A16_SFLOAT");
}

TEST(CliLut, MaterialOptionsReachTheTables) {
  TempDir dir;
  auto r = runCli({"lut", "--out", (dir / "a").string(), "--mode", "paper", "--eta", "1.3", "--color", "0.8,0.6,0.3",
                   "--beta-r", "5"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  auto j = nlohmann::json::parse(slurp(dir / "a" / "lut.json"));
  EXPECT_DOUBLE_EQ(j["material"]["eta"].get<double>(), 1.3);
  EXPECT_NEAR(j["material"]["betaR_rad"].get<double>(), 5.0 * 3.14159265358979 / 180.0, 1e-12);
  EXPECT_NEAR(j["material"]["absorption"][0].get<double>(), -std::log(0.8) / 2.0, 1e-12);
  ASSERT_EQ(runCli({"lut", "--out", (dir / "b").string(), "--mode", "paper"}).exitCode, 0);
  EXPECT_NE(slurp(dir / "a" / "N_rgb.pfm"), slurp(dir / "b" / "N_rgb.pfm"));
}

// Bad values of the material options are hp::Errors (exit 1, message naming the option); option
// syntax errors are CLI11's (non-zero, its own code). Either way nothing is written.
TEST(CliLut, BadOptionsFailWithAMessageAndWriteNothing) {
  TempDir dir;
  const std::string out = (dir / "lut").string();
  struct Case {
    std::vector<std::string> args;
    std::string message;
    bool hpError;
  };
  const std::vector<Case> cases = {
      {{"--eta", "0.5"}, "--eta 0.5", true},
      {{"--beta-r", "0"}, "--beta-r", true},
      {{"--color", "1.5,0.5,0.5"}, "--color", true},
      {{"--absorption", "-1,0,0"}, "--absorption", true},
      {{"--wc", "nan"}, "--wc", true},
      {{"--mode", "bogus"}, "--mode", false},
      {{"--color", "0.5,0.5"}, "--color", false},
      {{"--eta", "abc"}, "--eta", false},
  };
  for (const Case& c : cases) {
    std::vector<std::string> args = {"lut", "--out", out};
    args.insert(args.end(), c.args.begin(), c.args.end());
    auto r = runCli(args);
    if (c.hpError)
      EXPECT_EQ(r.exitCode, 1) << c.args[0] << ": " << r.err;
    else
      EXPECT_NE(r.exitCode, 0) << c.args[0] << ": " << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args[0] << ": " << r.err;
    EXPECT_EQ(filesIn(out), 0u) << c.args[0];
  }
  auto missingOut = runCli({"lut", "--mode", "paper"});
  EXPECT_NE(missingOut.exitCode, 0);
  EXPECT_NE(missingOut.err.find("--out"), std::string::npos) << missingOut.err;
  // --out naming an existing file: the directory cannot be created.
  hp::test::writeText(dir / "file", "x");
  auto notDir = runCli({"lut", "--out", (dir / "file").string(), "--mode", "paper"});
  EXPECT_EQ(notDir.exitCode, 1) << notDir.err;
  EXPECT_NE(notDir.err.find((dir / "file").string()), std::string::npos) << notDir.err;
}
}  // namespace
