// TressFX .tfx import (docs/THEORY.md §8.2): a synthetic file round-trips and imports to the same guides
// as the equivalent .hair data; every corruption is refused with a message naming the field.
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "engine/core/error.h"
#include "engine/core/hair/hair_import.h"
#include "engine/core/hair/scene.h"
#include "samples/tools/host/scene_file.h"
#include "engine/core/hair/tfx_file.h"
#include "tests/hair/tfx_cases.h"

namespace hp {
namespace {
// 300 strands x 16 vertices on the top of a 10 cm sphere, hanging down; UVs and thickness present.
TfxData syntheticTfx() {
  TfxData d;
  d.strandCount = 300;
  d.verticesPerStrand = 16;
  for (std::uint32_t s = 0; s < d.strandCount; ++s) {
    const float a = 0.7f * float(s), y = 1.0f - 0.8f * float(s) / float(d.strandCount), r = std::sqrt(1.0f - y * y);
    const glm::vec3 root(10.0f * r * std::cos(a), 10.0f * y, 10.0f * r * std::sin(a));
    for (std::uint32_t k = 0; k < d.verticesPerStrand; ++k)
      d.positions.emplace_back(root + glm::vec3(0.1f * float(k), -2.0f * float(k), 0.0f), k < 2 ? 0.0f : 1.0f);
    d.strandUVs.emplace_back(float(s) / 300.0f, 0.5f);
    d.strandThickness.push_back(0.5f + 0.001f * float(s));
  }
  return d;
}

void expectRefused(const std::vector<std::byte>& bytes, const std::string& needle) {
  try {
    decodeTfx(bytes, "bad.tfx");
    ADD_FAILURE() << "accepted; expected an error mentioning " << needle;
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("bad.tfx"), std::string::npos) << e.what();
  }
}
}  // namespace

TEST(TfxFile, SyntheticFileRoundTripsByteForByte) {
  const TfxData d = syntheticTfx();
  const auto bytes = encodeTfx(d);
  EXPECT_EQ(bytes.size(), 160u + 300u * 16u * 16u + 300u * 8u + 300u * 4u);
  const TfxData back = decodeTfx(bytes, "synthetic.tfx");
  EXPECT_EQ(back.strandCount, 300u);
  EXPECT_EQ(back.verticesPerStrand, 16u);
  EXPECT_EQ(back.positions, d.positions);
  EXPECT_EQ(back.strandUVs, d.strandUVs);
  EXPECT_EQ(back.strandThickness, d.strandThickness);
  EXPECT_TRUE(back.vertexUVs.empty() && back.vertexColors.empty());
  EXPECT_EQ(encodeTfx(back), bytes);
}

TEST(TfxFile, ImportGivesTheGuidesOfTheSameStrandsAsHair) {
  const auto dir = std::filesystem::temp_directory_path() / "hairpipe_tfx_test";
  std::filesystem::create_directories(dir);
  const TfxData d = syntheticTfx();
  const auto bytes = encodeTfx(d);
  std::ofstream(dir / "model.tfx", std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
  // The scene path: one guide per strand, roots exact, topology over the roots.
  Scene s = parseScene(R"({"model": {"source": "model.tfx", "scale": 0.01}, "density": {"totalStrands": 2000}})", "s.json", dir);
  EXPECT_EQ(s.model.kind, ModelSpec::Kind::Tfx);
  const HairAsset a = buildSceneAsset(s);
  ASSERT_EQ(a.guides.guideCount(), 300u);
  for (std::uint32_t g = 0; g < 300; ++g) EXPECT_EQ(a.guides.root(g), 0.01f * glm::vec3(d.positions[g * 16]));
  EXPECT_FALSE(a.topology.triangles.empty());
  // The same guides as the .hair import of the same points.
  HairImportOptions o;
  o.transform.scale = 0.01f;
  o.particlesPerGuide = s.growth.particlesPerGuide;
  o.segmentRatio = s.growth.segmentRatio;
  o.density.totalStrands = 2000;
  EXPECT_EQ(importHairAsset(tfxToHair(d), o, "x").guides.positions, a.guides.positions);
  std::filesystem::remove_all(dir);
}

TEST(TfxFile, CorruptTruncatedAndHostileFilesAreRefusedNamingTheField) {
  for (const test::TfxCase& c : test::tfxCases()) {
    SCOPED_TRACE(c.name);
    if (c.refusal.empty()) {
      const TfxData d = decodeTfx(c.bytes, "good.tfx");
      EXPECT_EQ(encodeTfx(d), c.bytes);
    } else {
      expectRefused(c.bytes, c.refusal);
    }
  }
}

// The .tfx fuzzer starts from these files; HAIRPIPE_UPDATE_CORPUS=1 rewrites them after a change of the cases.
TEST(TfxFile, SeedCorpusIsTheTestsFiles) {
  const auto dir = std::filesystem::path(HAIRPIPE_TEST_DATA_DIR).parent_path() / "fuzz" / "corpus" / "fuzz_tfx";
  const bool update = std::getenv("HAIRPIPE_UPDATE_CORPUS") != nullptr;
  std::size_t files = 0;
  for (const test::TfxCase& c : test::tfxCases()) {
    const auto path = dir / (c.name + ".tfx");
    if (update) {
      std::filesystem::create_directories(dir);
      std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(c.bytes.data()), std::streamsize(c.bytes.size()));
    }
    std::ifstream in(path, std::ios::binary);
    const std::vector<char> raw((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_TRUE(raw.size() == c.bytes.size() && std::memcmp(raw.data(), c.bytes.data(), raw.size()) == 0)
        << path << " differs from the test's case (HAIRPIPE_UPDATE_CORPUS=1 rewrites the corpus)";
    ++files;
  }
  for (const auto& entry : std::filesystem::directory_iterator(dir)) files -= entry.path().extension() == ".tfx";
  EXPECT_EQ(files, 0u) << "the corpus holds .tfx files that are no test case";
}
}  // namespace hp
