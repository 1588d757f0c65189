// `--mesh FILE` (issue 29): a character mesh given beside a model is drawn, collided with and bound to; the
// render says how the roots lie on it (stderr and --json), `inspect` describes meshes, and bad meshes or
// combinations are refused by message with nothing written.
#include <gtest/gtest.h>

#include <filesystem>

#include <nlohmann/json.hpp>

#include "engine/core/hair/hair_file.h"
#include "samples/tools/png_file.h"
#include "tests/hair/gltf_test_file.h"
#include "tests/hair/hair_test_util.h"
#include "tests/support/cli_runner.h"

using hp::test::expectRefused;
using hp::test::freshTempPath;
using hp::test::runCli;

namespace {
// 200 strands on the top of a 9 cm head, in centimetres, Z up, standing out and falling outside it; and the
// head as a skinned sphere (.glb, the same units and axes) with a clip.
struct Character {
  std::filesystem::path model, mesh;
};

Character centimetreCharacter() {
  Character c{freshTempPath("hairpipe_cli_mesh.hair"), freshTempPath("hairpipe_cli_mesh.glb")};
  hp::HairFileData d;
  d.strandCount = 200;
  d.defaultSegments = 4;
  for (std::uint32_t s = 0; s < d.strandCount; ++s) {
    const float a = 0.7f * float(s), z = 1.0f - 0.5f * float(s) / float(d.strandCount), r = std::sqrt(1.0f - z * z);
    const glm::vec3 root(9.0f * r * std::cos(a), 9.0f * r * std::sin(a), 9.0f * z);
    const glm::vec3 out = glm::normalize(glm::vec3(root.x, root.y, 0.0f) + glm::vec3(0.0f, 0.0f, -2.0f));
    for (int k = 0; k < 5; ++k) d.points.push_back(root + 1.0f * float(k) * glm::normalize(root) + 5.0f * float(k) * glm::vec3(out.x, out.y, 0.0f) * 0.2f + glm::vec3(0.0f, 0.0f, -4.0f * float(k)) * 0.5f);
  }
  hp::writeHairFile(c.model, d);
  hp::test::GltfTestMesh m = hp::test::uvSphere(9.0f);
  m.joints = {{"neck", -1, glm::vec3(0.0f)}, {"head", 0, glm::vec3(0.0f, 0.0f, 4.0f)}};
  for (std::size_t v = 0; v < m.positions.size(); ++v) {
    m.vertexJoints.emplace_back(m.positions[v].z > 3.0f ? 1 : 0, 0, 0, 0);
    m.vertexWeights.emplace_back(1.0f, 0.0f, 0.0f, 0.0f);
  }
  m.clips.push_back({"nod", 1, {0.0f, 2.0f}, {glm::quat(1, 0, 0, 0), glm::angleAxis(0.5f, glm::vec3(1, 0, 0))}});
  hp::test::writeBytes(c.mesh, hp::test::glbBytes(m));
  return c;
}
}  // namespace

TEST(CliCharacterMesh, ARenderWithAMeshReportsItsRootBinding) {
  const Character c = centimetreCharacter();
  const auto png = freshTempPath("hairpipe_cli_mesh.png");
  const auto r = runCli({"render", "--model", c.model.string(), "--mesh", c.mesh.string(), "--width", "96", "--height",
                         "72", "--density", "1000", "--frames", "2", "--no-shadows", "--json", "--out", png.string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("561 vertices, 960 triangles, 2 joints, 1 animations"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("fitted"), std::string::npos) << r.err;  // the mesh collides: no sphere is fitted
  const auto j = nlohmann::json::parse(r.out);
  const auto& mesh = j["guessed"]["mesh"];
  EXPECT_EQ(mesh["vertices"], 561);
  EXPECT_EQ(mesh["roots_far"], 0);
  EXPECT_LT(mesh["root_distance_max"].get<double>(), 0.002);  // metres: roots on the 9 cm sphere, facets sag 0.4 mm
  EXPECT_TRUE(std::filesystem::exists(png));
}

// simulate --json says how deep the hair got into the mesh: the crown strands hang outside the sphere.
TEST(CliCharacterMesh, SimulateReportsThePenetrationIntoTheMesh) {
  const Character c = centimetreCharacter();
  const auto r = runCli({"simulate", "--model", c.model.string(), "--mesh", c.mesh.string(), "--frames", "30",
                         "--animate", "shake", "--json"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j.contains("mesh_penetration")) << r.out;
  const auto& m = j["mesh_penetration"];
  EXPECT_EQ(m["particles"], 200 * 6);  // the free particles of 200 guides of 7
  EXPECT_LT(m["deepest"].get<double>(), 0.002) << r.out;  // the pearl radius keeps them out; 2 mm of grid error allowed
  EXPECT_GT(m["min_clearance"].get<double>(), -0.002);
}

namespace {
// The share of an image's pixels that are green hair (--color 0.2,0.75,0.25).
double greenShare(const std::filesystem::path& png) {
  const hp::RgbaImage image = hp::readPngRgba(png);
  std::size_t green = 0;
  for (std::size_t i = 0; i < image.pixels.size(); i += 4)
    green += image.pixels[i + 1] > image.pixels[i] + 12 && image.pixels[i + 1] > image.pixels[i + 2] + 12 ? 1u : 0u;
  return double(green) / double(image.width * image.height);
}
}  // namespace

// --animate clip:NAME plays the mesh's clip in render, simulate and view under validation (sync on): the
// body posed and collided with on the device, the roots on its bones; the hair stays in view and outside.
TEST(CliCharacterMesh, AClipPlaysInRenderSimulateAndView) {
  const Character c = centimetreCharacter();
  const auto png = freshTempPath("hairpipe_cli_clip.png");
  const std::vector<std::string> look = {"--width", "96", "--height", "72", "--density", "1500", "--color",
                                         "0.2,0.75,0.25", "--validation"};
  std::vector<std::string> args = {"render", "--model", c.model.string(), "--mesh", c.mesh.string(), "--animate",
                                   "clip:nod", "--frames", "20", "--out", png.string()};
  args.insert(args.end(), look.begin(), look.end());
  auto r = runCli(args);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const double posed = greenShare(png);
  args[6] = "none";  // the same frame without the clip
  r = runCli(args);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const double still = greenShare(png);
  std::cout << "hair share of the frame: " << posed << " in the clip, " << still << " still\n";
  EXPECT_GT(still, 0.01);
  EXPECT_GT(posed, 0.6 * still);  // the posed hair stays in view
  r = runCli({"simulate", "--model", c.model.string(), "--mesh", c.mesh.string(), "--animate", "clip:nod", "--frames",
              "30", "--json", "--validation"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["animation"], "clip:nod");
  EXPECT_GT(j["character_gpu_ms_per_frame_median"].get<double>(), 0.0);
  EXPECT_GT(j["mesh_penetration"]["min_clearance"].get<double>(), -0.002) << r.out;
  hp::test::Xvfb x;
  args = {"view", "--model", c.model.string(), "--mesh", c.mesh.string(), "--animate", "clip:nod", "--frames", "8",
          "--screenshot", png.string(), "--opacity-resolution", "32"};
  args.insert(args.end(), look.begin(), look.end());
  r = runCli(args, {x.displayEnv()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_GT(greenShare(png), 0.6 * still);
  expectRefused({"render", "--model", c.model.string(), "--mesh", c.mesh.string(), "--frames", "1", "--out", png.string()},
                {{{"--animate", "clip:walk"}, "no animation 'walk' (it has 'nod')"},
                 {{"--animate", "clip:"}, "--animate clip:NAME needs the clip's name"}});
}

TEST(CliCharacterMesh, InspectDescribesAMesh) {
  const Character c = centimetreCharacter();
  const auto r = runCli({"inspect", c.mesh.string(), "--json"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["kind"], "glTF");
  EXPECT_EQ(j["triangles"], 960);
  EXPECT_EQ(j["joint_names"], nlohmann::json({"neck", "head"}));
  ASSERT_EQ(j["animations"].size(), 1u);
  EXPECT_EQ(j["animations"][0]["name"], "nod");
  EXPECT_DOUBLE_EQ(j["animations"][0]["duration_s"].get<double>(), 2.0);
  const auto text = runCli({"inspect", c.mesh.string()});
  EXPECT_NE(text.out.find("glTF mesh: 561 vertices, 960 triangles"), std::string::npos) << text.out;
}

TEST(CliCharacterMesh, BadMeshesAreRefusedAndWriteNothing) {
  const Character c = centimetreCharacter();
  const auto broken = freshTempPath("hairpipe_cli_mesh_broken.ply");
  hp::test::writeText(broken, "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nend_header\n1 2 3\n");
  const auto png = freshTempPath("hairpipe_cli_mesh_refused.png");
  expectRefused({"render", "--width", "64", "--height", "48", "--frames", "1", "--out", png.string()},
                {{{"--model", c.model.string(), "--mesh", "body.fbx"}, "expected an .obj, .ply, .gltf, .glb or .tfxmesh"},
                 {{"--mesh", c.mesh.string()}, "a character mesh needs a model file"},
                 {{"--model", c.model.string(), "--mesh", broken.string()}, "the vertex element has no x, y and z"},
                 {{"--model", c.model.string(), "--mesh", "/nonexistent/body.glb"}, "/nonexistent/body.glb"}},
                png);
}
