// `hairpipe inspect`: what it reports for .hair and .obj files, and exit code 1 with a message that
// names the file and the problem for every kind of bad input.
#include <gtest/gtest.h>

#include <cstring>

#include <nlohmann/json.hpp>

#include "engine/core/hair/hair_file.h"
#include "engine/core/hair/hair_import.h"
#include "engine/core/hair/tfx_bone_file.h"
#include "samples/tools/host/synthetic_hair.h"
#include "tests/hair/hair_test_util.h"
#include "tests/support/cli_runner.h"

using hp::test::runCli;

namespace {
std::vector<std::byte> header(const char* sig, std::uint32_t strands, std::uint32_t points, std::uint32_t flags,
                              std::uint32_t defaultSegments) {
  std::vector<std::byte> b(128, std::byte{0});
  std::memcpy(b.data(), sig, 4);
  std::uint32_t fields[4] = {strands, points, flags, defaultSegments};
  std::memcpy(b.data() + 4, fields, sizeof fields);
  return b;
}

void appendFloats(std::vector<std::byte>& b, std::initializer_list<float> values) {
  for (float v : values) {
    std::size_t at = b.size();
    b.resize(at + 4);
    std::memcpy(b.data() + at, &v, 4);
  }
}

TEST(CliHairInspect, ReportsAHairModelAsJson) {
  hp::test::TempDir dir;
  hp::SyntheticHairOptions o;
  o.strands = 300;
  o.points = 300 * 12;
  hp::HairFileData d = hp::makeSyntheticHair(o);
  d.thickness.assign(d.points.size(), 0.01f);
  hp::writeHairFile(dir / "m.hair", d);
  auto r = runCli({"inspect", (dir / "m.hair").string(), "--json"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["strands"], 300);
  EXPECT_EQ(j["points"], 3600);
  EXPECT_LT(j["min_points_per_strand"].get<int>(), 12);
  EXPECT_GT(j["max_points_per_strand"].get<int>(), 12);
  EXPECT_EQ(j["arrays"], nlohmann::json({"segments", "points", "thickness"}));
  EXPECT_LT(j["bbox"]["min"][1].get<double>(), j["bbox"]["max"][1].get<double>());
  EXPECT_NEAR(j["head_sphere"]["radius"].get<double>(), 0.1, 1e-4);
  EXPECT_TRUE(j["head_sphere"]["fitted"].get<bool>());
  // The collider an import makes of that sphere (shrunk under every root), as the import makes it.
  EXPECT_FLOAT_EQ(j["head_sphere"]["collider_radius"].get<float>(),
                  hp::importHairAsset(d, hp::HairImportOptions{}, "m.hair").colliders.at(0).radius);
}

// The info field is free text from the file: bytes that are not UTF-8 are reported as U+FFFD, not a failed
// report (nlohmann's dump throws on them by default).
TEST(CliHairInspect, AnInfoFieldThatIsNotUtf8IsReportedAsJson) {
  hp::test::TempDir dir;
  hp::HairFileData d = hp::makeSyntheticHair({});
  const char text[] = "made \xff\xfe here";
  d.info.fill('\0');
  std::memcpy(d.info.data(), text, sizeof(text) - 1);
  hp::writeHairFile(dir / "m.hair", d);
  auto r = runCli({"inspect", (dir / "m.hair").string(), "--json"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["info"], "made \ufffd\ufffd here");
}

TEST(CliHairInspect, TextOutput) {
  hp::test::TempDir dir;
  hp::writeHairFile(dir / "m.hair", hp::makeSyntheticHair({}));
  auto r = runCli({"inspect", (dir / "m.hair").string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  for (const char* line : {"strands: 1000", "points: 64000", "points per strand: min ", "arrays: segments points",
                           "bbox: min (", "head sphere: center ("})
    EXPECT_NE(r.out.find(line), std::string::npos) << line << "\n" << r.out;
}

TEST(CliHairInspect, ReportsAnObjScalp) {
  auto r = runCli({"inspect", std::string(HAIRPIPE_TEST_DATA_DIR) + "/scalp_cap.obj", "--json"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["vertices"], 49);
  EXPECT_EQ(j["triangles"], 84);
  EXPECT_NEAR(j["head_sphere"]["radius"].get<double>(), 1.0, 1e-4);
  EXPECT_FALSE(j["head_sphere"].contains("collider_radius"));  // a scalp's fitted sphere is drawn as it is
}

struct BadHair {
  const char* name;
  std::vector<std::byte> bytes;
  const char* message;
};

std::vector<BadHair> badHairFiles() {
  std::vector<BadHair> cases;
  auto twoStrands = header("HAIR", 2, 4, 2, 1);
  appendFloats(twoStrands, {0, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 0});
  cases.push_back({"short", std::vector<std::byte>(twoStrands.begin(), twoStrands.begin() + 60),
                   "short header: 60 bytes"});
  auto sig = twoStrands;
  std::memcpy(sig.data(), "RIAH", 4);
  cases.push_back({"signature", sig, "wrong signature \"RIAH\""});
  cases.push_back({"truncated", std::vector<std::byte>(twoStrands.begin(), twoStrands.end() - 8), "truncated arrays"});
  auto huge = header("HAIR", 1, 0xfffffff0u, 2, 1);
  cases.push_back({"huge", huge, "truncated arrays: the header's counts need"});
  cases.push_back({"zero", header("HAIR", 0, 0, 2, 1), "zero strands"});
  auto sum = header("HAIR", 2, 4, 2, 2);  // 2 strands x 3 points != 4
  appendFloats(sum, {0, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 0});
  cases.push_back({"sum", sum, "sum to 6 points but the point count is 4"});
  auto nan = header("HAIR", 2, 4, 2, 1);
  appendFloats(nan, {0, 0, 0, 0, 1, 0, 1, 0, 0, 1, NAN, 0});
  cases.push_back({"nan", nan, "point 3 (strand 1) is not finite"});
  auto inf = header("HAIR", 2, 4, 2, 1);
  appendFloats(inf, {0, 0, 0, 0, 1, 0, INFINITY, 0, 0, 1, 1, 0});
  cases.push_back({"inf", inf, "point 2 (strand 1) is not finite"});
  auto onePoint = header("HAIR", 2, 3, 3, 0);
  for (std::uint16_t s : {std::uint16_t(1), std::uint16_t(0)}) {
    onePoint.resize(onePoint.size() + 2);
    std::memcpy(onePoint.data() + onePoint.size() - 2, &s, 2);
  }
  appendFloats(onePoint, {0, 0, 0, 0, 1, 0, 1, 0, 0});
  cases.push_back({"onepoint", onePoint, "strand 1 has 1 point (0 segments); a strand needs at least 2"});
  return cases;
}

TEST(CliHairInspect, BadHairFilesExitOneNamingFileAndProblem) {
  hp::test::TempDir dir;
  for (const auto& c : badHairFiles()) {
    auto path = dir / (std::string(c.name) + ".hair");
    hp::test::writeBytes(path, c.bytes);
    auto r = runCli({"inspect", path.string()});
    EXPECT_EQ(r.exitCode, 1) << c.name;
    EXPECT_NE(r.err.find(path.string() + ": "), std::string::npos) << c.name << ": " << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.name << ": " << r.err;
    EXPECT_TRUE(r.out.empty()) << c.name;
  }
}

// A TressFX skinning file: its bones, strands and weights; a corrupt one exits 1 naming the problem.
TEST(CliHairInspect, ReportsATressFxSkinningFile) {
  hp::test::TempDir dir;
  hp::TfxBoneData d;
  d.boneIndices = {0, 1};
  d.boneNames = {"head", "jaw"};
  d.strands = {{0, {0, -1, -1, -1}, {1.0f, 0.0f, 0.0f, 0.0f}}, {1, {0, 1, -1, -1}, {0.6f, 0.6f, 0.0f, 0.0f}}};
  hp::test::writeBytes(dir / "hair.tfxbone", hp::encodeTfxBone(d));
  auto r = runCli({"inspect", (dir / "hair.tfxbone").string(), "--json"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["format"], "tfxbone");
  EXPECT_EQ(j["bones"], 2);
  EXPECT_EQ(j["bone_names"], (std::vector<std::string>{"head", "jaw"}));
  EXPECT_EQ(j["strands"], 2);
  EXPECT_EQ(j["most_influences_per_strand"], 2);
  EXPECT_EQ(j["strands_with_weights_not_summing_to_1"], 1);
  r = runCli({"inspect", (dir / "hair.tfxbone").string()});
  EXPECT_NE(r.out.find("TressFX skinning: 2 bones, 2 strands"), std::string::npos) << r.out;
  std::vector<std::byte> bytes = hp::encodeTfxBone(d);
  bytes.resize(bytes.size() - 1);
  hp::test::writeBytes(dir / "cut.tfxbone", bytes);
  r = runCli({"inspect", (dir / "cut.tfxbone").string()});
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("cut.tfxbone: strand count 2 needs 72 bytes, the file has 71 left"), std::string::npos) << r.err;
}

TEST(CliHairInspect, BadObjAndUnknownTypesExitOne) {
  hp::test::TempDir dir;
  hp::test::writeText(dir / "bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -4\n");
  auto r = runCli({"inspect", (dir / "bad.obj").string()});
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("bad.obj: face 1: negative vertex index points before the first vertex"), std::string::npos)
      << r.err;
  r = runCli({"inspect", (dir / "model.fbx").string()});
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("model.fbx: unknown file type (expected .hair, .tfx, .tfxbone, .obj, .ply, .gltf, .glb or .tfxmesh)"), std::string::npos)
      << r.err;
  r = runCli({"inspect", (dir / "missing.hair").string()});
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("missing.hair: cannot open"), std::string::npos) << r.err;
}
}  // namespace
