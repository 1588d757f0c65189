// Every command checks its outputs before any work: an output naming one of its inputs is refused and
// the input is left byte-identical; a folder where a file is expected (and the reverse) is refused;
// missing folders are created.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <chrono>
#include <fstream>
#include <iostream>
#include <sstream>

#include "tests/hair/hair_test_util.h"
#include "tests/support/cli_runner.h"

using hp::test::runCli;

namespace {
const std::string kCapObj = std::string(HAIRPIPE_TEST_DATA_DIR) + "/scalp_cap.obj";

std::string contentsOf(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Runs the command, expects exit 1 with `needle` on stderr and `input` unchanged.
void expectInputKept(const std::vector<std::string>& args, const std::filesystem::path& input, const std::string& needle) {
  const std::string before = contentsOf(input);
  const auto r = runCli(args);
  EXPECT_EQ(r.exitCode, 1) << r.err;
  EXPECT_NE(r.err.find(needle), std::string::npos) << r.err;
  EXPECT_EQ(contentsOf(input), before) << "the input was modified";
}

TEST(CliOutputPaths, GrowRefusesToOverwriteItsScalp) {
  hp::test::TempDir dir;
  std::filesystem::copy_file(kCapObj, dir / "a.obj");
  const std::string scalp = (dir / "a.obj").string();
  expectInputKept({"grow", "--scalp", scalp, "--out", scalp}, scalp, "is the input given by --scalp");
  // The same file through another spelling of its path.
  expectInputKept({"grow", "--scalp", scalp, "--out", (dir.path() / "." / "a.obj").string()}, scalp,
                  "is the input given by --scalp");
}

TEST(CliOutputPaths, RenderAndStrandsRefuseToOverwriteTheirModel) {
  hp::test::TempDir dir;
  const std::string hair = (dir / "m.hair").string();
  ASSERT_EQ(runCli({"grow", "--scalp", kCapObj, "--out", hair, "--particles", "4"}).exitCode, 0);
  expectInputKept({"render", "--model", hair, "--out", hair, "--frames", "1"}, hair, "is the input given by --model");
  expectInputKept({"render", "--model", hair, "--dump-strands", hair, "--frames", "1"}, hair,
                  "--dump-strands " + hair + ": is the input given by --model");
  expectInputKept({"strands", "--model", hair, "--out", hair}, hair, "is the input given by --model");
  expectInputKept({"simulate", "--model", hair, "--out", hair, "--frames", "1"}, hair, "is the input given by --model");
}

TEST(CliOutputPaths, SceneModelIsAnInputToo) {
  hp::test::TempDir dir;
  ASSERT_EQ(runCli({"grow", "--scalp", kCapObj, "--out", (dir / "m.hair").string(), "--particles", "4"}).exitCode, 0);
  hp::test::writeText(dir / "s.json", R"({"model": "m.hair"})");
  expectInputKept({"strands", "--scene", (dir / "s.json").string(), "--out", (dir / "m.hair").string()},
                  dir / "m.hair", "is the input given by the scene's model");
  expectInputKept({"strands", "--scene", (dir / "s.json").string(), "--out", (dir / "s.json").string()},
                  dir / "s.json", "is the input given by --scene");
}

TEST(CliOutputPaths, AnExportFolderNeverOverwritesAnInputInside) {
  hp::test::TempDir dir;
  const std::string hair = (dir / "strands.hair").string();
  ASSERT_EQ(runCli({"grow", "--scalp", kCapObj, "--out", hair, "--particles", "4"}).exitCode, 0);
  expectInputKept({"render", "--model", hair, "--export-frame", dir.path().string(), "--frames", "1"}, hair,
                  "--export-frame " + hair + ": is the input given by --model");
  hp::test::writeText(dir / "frame.json", "{}");  // the default head; the scene file itself is the input
  expectInputKept({"render", "--scene", (dir / "frame.json").string(), "--export-frame", dir.path().string(),
                   "--frames", "1"},
                  dir / "frame.json", "is the input given by --scene");
}

TEST(CliOutputPaths, BrdfRefusesToOverwriteItsQueries) {
  hp::test::TempDir dir;
  hp::test::writeText(dir / "q.csv", "0,0,1,0,0,1,1,0,0\n");
  expectInputKept({"brdf", "--in", (dir / "q.csv").string(), "--out", (dir / "q.csv").string()}, dir / "q.csv",
                  "is the input given by --in");
}

TEST(CliOutputPaths, FoldersAndFilesAreNotConfused) {
  hp::test::TempDir dir;
  std::filesystem::create_directories(dir / "taken");
  auto r = runCli({"grow", "--scalp", kCapObj, "--out", (dir / "taken").string()});
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("is a folder, expected a file name"), std::string::npos) << r.err;
  hp::test::writeText(dir / "file", "x");
  r = runCli({"lut", "--out", (dir / "file").string()});
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("is a file, expected a folder"), std::string::npos) << r.err;
  r = runCli({"grow", "--scalp", kCapObj, "--out", (dir / "file" / "x.hair").string()});
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("cannot create the folder"), std::string::npos) << r.err;
}

TEST(CliOutputPaths, MissingFoldersAreCreated) {
  hp::test::TempDir dir;
  const auto out = dir / "a" / "b" / "g.hair";
  const auto r = runCli({"grow", "--scalp", kCapObj, "--out", out.string(), "--particles", "4"});
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(std::filesystem::is_regular_file(out));
}
}  // namespace

// An output where no file can be created (/proc: even root cannot) is refused before any work: render
// and reference fail at once, naming the folder, instead of after the frame.
// A device or FIFO is refused as an output before any work, and left as it was (renaming over it made it a
// regular file: /dev/full did, and as root /dev/null would).
TEST(CliOutputPaths, ADeviceOrFifoIsNeverAnOutput) {
  hp::test::TempDir dir;
  ASSERT_EQ(::mkfifo((dir / "pipe").c_str(), 0600), 0);
  const auto r = runCli({"strands", "--density", "10", "--out", (dir / "pipe").string()});
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("exists and is not a regular file"), std::string::npos) << r.err;
  EXPECT_EQ(std::filesystem::status(dir / "pipe").type(), std::filesystem::file_type::fifo);
}

TEST(CliOutputPaths, AnUnwritableOutputIsRefusedBeforeAnyWork) {
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"render", "--width", "32", "--height", "32", "--out", "/proc/x.png"},
        std::vector<std::string>{"reference", "--width", "32", "--height", "24", "--spp", "1", "--out", "/proc/x.pfm"},
        std::vector<std::string>{"simulate", "--frames", "2", "--out", "/proc/x.hair"}}) {
    const auto start = std::chrono::steady_clock::now();
    const auto r = runCli(args);
    EXPECT_EQ(r.exitCode, 1) << args[0] << ": " << r.err;
    EXPECT_NE(r.err.find(": cannot create a file in /proc"), std::string::npos) << args[0] << ": " << r.err;
    EXPECT_EQ(r.err.find("wrote"), std::string::npos) << r.err;
    std::cout << args[0] << " refused in "
              << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() << " s\n";
  }
}
