// Environment files (samples/tools/environment_file.h), on the host: a Radiance .hdr (flat and run-length) and a
// 3-channel .pfm read back their texels exactly; what is not an environment is refused by a message naming the
// file and the problem (another format, a size past 8192x4096 or past what the file can hold before anything
// is decoded, a 1-channel PFM, a negative radiance, a file that is not RGBE at all, a truncated file, a broken
// run).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "engine/core/error.h"
#include "samples/tools/environment_file.h"
#include "samples/tools/linear_image.h"
#include "tests/support/cli_runner.h"
#include "tests/support/refusal.h"

using namespace hp;

namespace {
// An uncompressed RGBE file (narrower than 8 texels, so stb reads flat pixels), `height` rows of `width`.
void writeHdr(const std::filesystem::path& path, int width, int height, const std::string& pixels) {
  std::ofstream out(path, std::ios::binary);
  out << "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y " << height << " +X " << width << "\n" << pixels;
}

std::string errorOf(const std::filesystem::path& path) {
  return test::refusalOf([&] { readEnvironmentFile(path); });
}
}  // namespace

TEST(EnvironmentFile, ReadsRadianceHdrTexelsExactly) {
  const auto dir = test::freshTempPath("hairpipe_environment_file");
  std::filesystem::create_directories(dir);
  // RGBE (128, 64, 32, 129) is (1, 0.5, 0.25); (0, 0, 0, 0) is black; (128, 128, 128, 131) is 4.
  const std::string texels = std::string("\x80\x40\x20\x81", 4) + std::string(4, '\0') + std::string("\x80\x80\x80\x83", 4);
  writeHdr(dir / "sky.hdr", 3, 2, texels + texels);
  const EnvironmentMap map = readEnvironmentFile(dir / "sky.hdr");
  ASSERT_EQ(map.width, 3u);
  ASSERT_EQ(map.height, 2u);
  EXPECT_EQ(map.texels[0], glm::vec3(1.0f, 0.5f, 0.25f));
  EXPECT_EQ(map.texels[1], glm::vec3(0.0f));
  EXPECT_EQ(map.texels[5], glm::vec3(4.0f));
  std::filesystem::remove_all(dir);
}

// A run-length scanline (2, 2, width) of 8 texels: one run per channel, then a run that is cut short, a run of
// 0 and a run past the scanline, each refused by name (Debian's stb_image 2.27 loops forever on the first).
TEST(EnvironmentFile, ReadsRunLengthScanlinesAndRefusesBrokenRuns) {
  const auto dir = test::freshTempPath("hairpipe_environment_rle");
  std::filesystem::create_directories(dir);
  const std::string start("\x02\x02\x00\x08", 4);
  const std::string runs = std::string("\x88\x80\x88\x40\x88\x20\x88\x81", 8);  // 8 x (128, 64, 32, 129)
  writeHdr(dir / "rle.hdr", 8, 1, start + runs);
  const EnvironmentMap map = readEnvironmentFile(dir / "rle.hdr");
  ASSERT_EQ(map.texels.size(), 8u);
  EXPECT_EQ(map.texels[7], glm::vec3(1.0f, 0.5f, 0.25f));
  writeHdr(dir / "cut.hdr", 8, 1, start + runs.substr(0, 3));
  EXPECT_NE(errorOf(dir / "cut.hdr").find("truncated"), std::string::npos) << errorOf(dir / "cut.hdr");
  const std::string padding(8, '\x01');  // the rest of a scanline's smallest size, after the broken run
  writeHdr(dir / "zero.hdr", 8, 1, start + std::string(1, '\0') + padding);
  EXPECT_NE(errorOf(dir / "zero.hdr").find("a run of 0"), std::string::npos) << errorOf(dir / "zero.hdr");
  writeHdr(dir / "long.hdr", 8, 1, start + std::string("\x89\x80", 2) + padding);
  EXPECT_NE(errorOf(dir / "long.hdr").find("a run of 9 past its scanline"), std::string::npos) << errorOf(dir / "long.hdr");
  writeHdr(dir / "flat_cut.hdr", 3, 2, std::string("\x80\x40\x20\x81", 4));
  EXPECT_NE(errorOf(dir / "flat_cut.hdr").find("truncated"), std::string::npos) << errorOf(dir / "flat_cut.hdr");
  // Long enough for two run-length scanlines at their smallest, but the first spends its bytes on literal
  // runs: the second ends early, found while decoding.
  std::string literal = start;
  for (int channel = 0; channel < 4; ++channel) literal += std::string(1, '\x08') + std::string(8, '\x40');
  writeHdr(dir / "late_cut.hdr", 8, 2, literal + start);
  EXPECT_NE(errorOf(dir / "late_cut.hdr").find("truncated: the pixels end early"), std::string::npos)
      << errorOf(dir / "late_cut.hdr");
  std::filesystem::remove_all(dir);
}

TEST(EnvironmentFile, ReadsAThreeChannelPfm) {
  const auto dir = test::freshTempPath("hairpipe_environment_pfm");
  std::filesystem::create_directories(dir);
  LinearImage image(4, 2, 3);
  for (std::size_t i = 0; i < image.values.size(); ++i) image.values[i] = 0.25f * float(i);
  writePfm(dir / "sky.pfm", image);
  const EnvironmentMap map = readEnvironmentFile(dir / "sky.pfm");
  ASSERT_EQ(map.texels.size(), 8u);
  EXPECT_EQ(map.texels[7], glm::vec3(0.25f * 21, 0.25f * 22, 0.25f * 23));
  std::filesystem::remove_all(dir);
}

TEST(EnvironmentFile, RefusesWhatIsNotAnEnvironmentByName) {
  const auto dir = test::freshTempPath("hairpipe_environment_bad");
  std::filesystem::create_directories(dir);
  writeHdr(dir / "huge.hdr", 9000, 9000, "");
  EXPECT_NE(errorOf(dir / "huge.hdr").find("9000x9000 texels is empty or larger than"), std::string::npos)
      << errorOf(dir / "huge.hdr");
  // Within the size allowed but not in the file: refused before the 400 MB image is made.
  writeHdr(dir / "claims.hdr", 8192, 4096, std::string("\x02\x02\x20\x00", 4));
  EXPECT_NE(errorOf(dir / "claims.hdr").find("truncated: 4 bytes cannot hold 4096 scanlines of 8192 texels"),
            std::string::npos)
      << errorOf(dir / "claims.hdr");
  std::ofstream(dir / "text.hdr") << "not an image\n";
  EXPECT_NE(errorOf(dir / "text.hdr").find("not a Radiance .hdr"), std::string::npos) << errorOf(dir / "text.hdr");
  std::ofstream(dir / "sky.exr") << "x";
  EXPECT_NE(errorOf(dir / "sky.exr").find(".hdr or a .pfm"), std::string::npos) << errorOf(dir / "sky.exr");
  writePfm(dir / "grey.pfm", LinearImage(2, 2, 1));
  EXPECT_NE(errorOf(dir / "grey.pfm").find("3 channels"), std::string::npos) << errorOf(dir / "grey.pfm");
  LinearImage negative(2, 1, 3);
  negative.values[1] = -0.5f;
  writePfm(dir / "negative.pfm", negative);
  EXPECT_NE(errorOf(dir / "negative.pfm").find("negative"), std::string::npos) << errorOf(dir / "negative.pfm");
  EXPECT_NE(errorOf(dir / "missing.hdr").find("missing.hdr"), std::string::npos) << errorOf(dir / "missing.hdr");
  std::filesystem::remove_all(dir);
}
