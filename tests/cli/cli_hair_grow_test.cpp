// `hairpipe grow`: guides from an OBJ scalp to a .hair file, options, and atomic output: bad input
// exits 1 with a message and leaves no file (or the previous file untouched).
#include <gtest/gtest.h>

#include "engine/core/hair/hair_file.h"
#include "tests/hair/hair_test_util.h"
#include "tests/support/cli_runner.h"

using hp::test::runCli;
using hp::test::filesIn;

namespace {
const std::string kCap = std::string(HAIRPIPE_TEST_DATA_DIR) + "/scalp_cap.obj";

TEST(CliHairGrow, GrowsOneGuidePerScalpVertex) {
  hp::test::TempDir dir;
  auto out = (dir / "guides.hair").string();
  auto r = runCli({"grow", "--scalp", kCap, "--out", out, "--particles", "9", "--length", "0.5", "--ratio", "1.2",
                   "--variation", "0"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("grew 49 guides x 9 particles"), std::string::npos) << r.out;
  hp::HairFileData d = hp::readHairFile(out);
  EXPECT_EQ(d.strandCount, 49u);
  EXPECT_EQ(d.pointCount(), 49u * 9u);
  EXPECT_NEAR(glm::length(d.points[0]), 1.0f, 1e-5f);  // root on the unit cap
  EXPECT_NEAR(glm::length(d.points[8]), 1.5f, 0.01f);   // the pole guide: straight out along the normal, 0.5 long
  EXPECT_EQ(filesIn(dir.path()), 1u);
}

TEST(CliHairGrow, SameSeedSameBytes) {
  hp::test::TempDir dir;
  auto a = (dir / "a.hair").string(), b = (dir / "b.hair").string();
  ASSERT_EQ(runCli({"grow", "--scalp", kCap, "--out", a, "--bend", "0.4", "--fit-collider"}).exitCode, 0);
  ASSERT_EQ(runCli({"grow", "--scalp", kCap, "--out", b, "--bend", "0.4", "--fit-collider"}).exitCode, 0);
  std::ifstream fa(a, std::ios::binary), fb(b, std::ios::binary);
  std::string sa((std::istreambuf_iterator<char>(fa)), {}), sb((std::istreambuf_iterator<char>(fb)), {});
  EXPECT_EQ(sa, sb);
}

TEST(CliHairGrow, BadScalpLeavesNoOutput) {
  hp::test::TempDir dir;
  hp::test::writeText(dir / "bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n");
  auto out = dir / "out.hair";
  auto r = runCli({"grow", "--scalp", (dir / "bad.obj").string(), "--out", out.string()});
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("bad.obj: face 1: vertex index 9 is out of range (the file has 3 vertices)"), std::string::npos)
      << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));
  EXPECT_EQ(filesIn(dir.path()), 1u);  // just bad.obj: no temporary left behind
}

TEST(CliHairGrow, FailureKeepsThePreviousOutput) {
  hp::test::TempDir dir;
  auto out = dir / "out.hair";
  hp::test::writeText(out, "previous");
  hp::test::writeText(dir / "nofaces.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
  auto r = runCli({"grow", "--scalp", (dir / "nofaces.obj").string(), "--out", out.string()});
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("nofaces.obj: no faces"), std::string::npos) << r.err;
  std::ifstream f(out);
  std::string content((std::istreambuf_iterator<char>(f)), {});
  EXPECT_EQ(content, "previous");
}

TEST(CliHairGrow, BadOptionsExitOne) {
  hp::test::TempDir dir;
  auto out = (dir / "o.hair").string();
  auto r = runCli({"grow", "--scalp", kCap, "--out", out, "--particles", "80"});
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("particles per guide must be in [2, 64], got 80"), std::string::npos) << r.err;
  r = runCli({"grow", "--scalp", kCap, "--out", out, "--up", "x"});
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("up axis must be \"y\" or \"z\", got \"x\""), std::string::npos) << r.err;
  r = runCli({"grow", "--scalp", kCap, "--out", out, "--ratio", "0.5"});
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("segmentRatio must be in [1, 4]"), std::string::npos) << r.err;
  // Missing folders are created (the rule of every command); one under a file cannot be.
  hp::test::writeText(dir / "plain", "x");
  r = runCli({"grow", "--scalp", kCap, "--out", (dir / "plain/sub/o.hair").string()});
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("o.hair: cannot create the folder"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));
}
}  // namespace
