// The material tables on disk (engine/core/shading/lut_encoding.h, lut_cache.h loadOrBuildLut): what is read back
// is the tables bit for bit, in every mode; a damaged entry is built again and replaced; a malformed encoding
// is refused.
#include <gtest/gtest.h>

#include <cstring>

#include "engine/core/shading/lut_cache.h"
#include "engine/core/shading/lut_encoding.h"
#include "tests/hair/hair_test_util.h"

using namespace hp;

namespace {
bool sameBits(const std::vector<float>& a, const std::vector<float>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

void expectSameTables(const MarschnerLut& a, const MarschnerLut& b) {
  EXPECT_EQ(a.mode, b.mode);
  EXPECT_EQ(a.material, b.material);
  EXPECT_EQ(a.parameterisation, b.parameterisation);
  ASSERT_EQ(a.textures.size(), b.textures.size());
  for (std::size_t i = 0; i < a.textures.size(); ++i) {
    const LutTexture &s = a.textures[i], &t = b.textures[i];
    EXPECT_EQ(s.name, t.name);
    EXPECT_EQ(s.width, t.width);
    EXPECT_EQ(s.height, t.height);
    EXPECT_EQ(s.channels, t.channels);
    EXPECT_EQ(s.format, t.format);
    EXPECT_EQ(s.scale, t.scale);
    EXPECT_EQ(s.channelNames, t.channelNames);
    EXPECT_EQ(s.uAxis, t.uAxis);
    EXPECT_EQ(s.vAxis, t.vAxis);
    EXPECT_TRUE(sameBits(s.data, t.data)) << "texture " << s.name;
  }
  const MultipleScatteringTables &m = a.multipleScattering, &n = b.multipleScattering;
  EXPECT_EQ(m.forwardAlbedo, n.forwardAlbedo);
  EXPECT_EQ(m.backAlbedo, n.backAlbedo);
  EXPECT_EQ(m.meanR, n.meanR);
  EXPECT_EQ(m.meanTT, n.meanTT);
  EXPECT_EQ(m.meanTRT, n.meanTRT);
  EXPECT_EQ(m.backScatter, n.backScatter);
  EXPECT_EQ(m.backShift, n.backShift);
  EXPECT_EQ(m.backWidth, n.backWidth);
}

HairMaterial unusualMaterial() {
  HairMaterial m;
  m.betaR = 0.111;  // no other test of this process builds it
  m.absorption = {0.3, 0.5, 0.9};
  return m;
}
}  // namespace

TEST(LutEncoding, EveryModeDecodesToTheSameTablesBitForBit) {
  for (LutMode mode : {LutMode::Direct, LutMode::Paper, LutMode::Float, LutMode::Physical}) {
    SCOPED_TRACE(lutModeName(mode));
    const MarschnerLut built = buildLut(mode, unusualMaterial());
    expectSameTables(decodeLut(encodeLut(built)), built);
  }
}

TEST(LutEncoding, ATruncatedOrLongerEncodingIsRefused) {
  const std::vector<std::byte> bytes = encodeLut(buildLut(LutMode::Paper, unusualMaterial()));
  for (std::size_t cut : {std::size_t(0), std::size_t(3), bytes.size() / 2, bytes.size() - 1})
    EXPECT_THROW(decodeLut(std::span(bytes).first(cut)), Error) << "cut at " << cut;
  std::vector<std::byte> longer = bytes;
  longer.push_back(std::byte{0});
  EXPECT_THROW(decodeLut(longer), Error);
}

TEST(LutDiskCache, TablesReadBackEqualTheBuiltOnesAndADamagedEntryIsBuiltAgain) {
  test::TempDir dir;
  const DiskCache disk(dir.path());
  const MarschnerLut built = buildLut(LutMode::Float, unusualMaterial());
  expectSameTables(loadOrBuildLut(disk, LutMode::Float, unusualMaterial()), built);  // built, stored
  const auto files = std::distance(std::filesystem::directory_iterator(dir.path()), {});
  ASSERT_EQ(files, 1);
  const std::filesystem::path entry = std::filesystem::directory_iterator(dir.path())->path();
  const ino_t stored = test::inodeOf(entry);
  expectSameTables(loadOrBuildLut(disk, LutMode::Float, unusualMaterial()), built);  // read back
  EXPECT_EQ(test::inodeOf(entry), stored) << "built again instead of read";
  // Damaged: a byte in the middle (a texel's) flipped in place. Built again, and the entry replaced by a whole one.
  const std::vector<std::byte> whole = test::readBytes(entry);
  std::vector<std::byte> damaged = whole;
  damaged[damaged.size() / 2] ^= std::byte{0xff};
  test::writeBytes(entry, damaged);
  expectSameTables(loadOrBuildLut(disk, LutMode::Float, unusualMaterial()), built);
  EXPECT_NE(test::inodeOf(entry), stored) << "the damaged entry was not replaced";
  EXPECT_TRUE(test::readBytes(entry) == whole) << "the entry written again differs";
  // Other options are other tables.
  LutBuildOptions wide;
  wide.floatFormat = LutFormat::RGBA32F;
  expectSameTables(loadOrBuildLut(disk, LutMode::Float, unusualMaterial(), wide),
                   buildLut(LutMode::Float, unusualMaterial(), wide));
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir.path()), {}), 2);
}
