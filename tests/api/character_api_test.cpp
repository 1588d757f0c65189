// A character mesh through the public API (issue 29): loadAsset with AssetSource::mesh binds the roots to
// it and says how (Asset::character), meshSkinning weights each guide by the triangle it grows from,
// meshClipPose poses the skeleton from the mesh's clips, and an instance takes both as Kind::Bones input
// under validation. Bad meshes and missing clips fail by message.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <optional>
#include <string>

#include "hairpipe/hairpipe.h"
#include "tests/hair/gltf_test_file.h"

namespace {
using ::testing::HasSubstr;

// 120 guides standing 6 cm out of the crown of a 9 cm sphere (.hair), and the sphere as a .glb skinned to a
// "neck" joint and a "head" joint 5 cm up that every vertex above 3 cm follows, with a clip "nod" turning
// the head 90 degrees about x in one second.
// A folder per test: ctest runs this file's tests in parallel processes, and each removes its folder at its end.
struct Files {
  std::filesystem::path dir = std::filesystem::path(::testing::TempDir()) /
                              (std::string("hairpipe_character_api_") +
                               ::testing::UnitTest::GetInstance()->current_test_info()->name());
  std::filesystem::path hair = dir / "crown.hair", mesh = dir / "head.glb";
};

void writeApiFile(const std::filesystem::path& path, const void* data, std::size_t size) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  ASSERT_NE(f, nullptr);
  std::fwrite(data, 1, size, f);
  std::fclose(f);
}

std::vector<glm::vec3> apiCrownRoots() {
  std::vector<glm::vec3> roots;
  for (int i = 0; i < 120; ++i) {
    const float a = 0.61f * float(i), up = 0.1f + 0.5f * float(i) / 119.0f;
    roots.push_back(0.0905f * glm::normalize(glm::vec3(std::sin(a) * up, 1.0f, std::cos(a) * up)));
  }
  return roots;
}

Files writeFiles() {
  Files f;
  std::filesystem::create_directories(f.dir);
  // .hair: header (points only, 4 segments), then 5 points per strand.
  std::vector<float> points;
  for (const glm::vec3& r : apiCrownRoots())
    for (int k = 0; k < 5; ++k)
      for (int c = 0; c < 3; ++c) points.push_back(r[c] * (1.0f + 0.17f * float(k)));
  unsigned char header[128] = {'H', 'A', 'I', 'R'};
  const std::uint32_t fields[4] = {120, 600, 2, 4};  // strands, points, arrays (points), default segments
  std::memcpy(header + 4, fields, sizeof fields);
  std::vector<unsigned char> bytes(header, header + 128);
  const auto* p = reinterpret_cast<const unsigned char*>(points.data());
  bytes.insert(bytes.end(), p, p + points.size() * sizeof(float));
  writeApiFile(f.hair, bytes.data(), bytes.size());
  hp::test::GltfTestMesh m = hp::test::uvSphere(0.09f);
  m.joints = {{"neck", -1, glm::vec3(0.0f)}, {"head", 0, glm::vec3(0.0f, 0.05f, 0.0f)}};
  for (const glm::vec3& v : m.positions) {
    m.vertexJoints.emplace_back(v.y > 0.03f ? 1 : 0, 0, 0, 0);
    m.vertexWeights.emplace_back(1.0f, 0.0f, 0.0f, 0.0f);
  }
  m.clips.push_back({"nod", 1, {0.0f, 1.0f}, {glm::quat(1, 0, 0, 0), glm::angleAxis(1.5707964f, glm::vec3(1, 0, 0))}});
  const std::vector<std::byte> glb = hp::test::glbBytes(m);
  writeApiFile(f.mesh, glb.data(), glb.size());
  return f;
}

template <class T>
std::string meshFailureOf(const T& result) {
  EXPECT_FALSE(result.ok());
  return result.ok() ? std::string("(succeeded)") : result.message();
}

hairpipe::Asset loadCharacter(const Files& f) {
  hairpipe::AssetSource source;
  source.path = f.hair.string();
  source.mesh = f.mesh.string();
  source.density.totalStrands = 600;
  hairpipe::Result<hairpipe::Asset> a = hairpipe::loadAsset(source);
  EXPECT_TRUE(a.ok()) << a.message();
  return std::move(a).value();
}
}  // namespace

TEST(CharacterApi, RootsBindToTheMeshAndFollowItsBones) {
  const Files f = writeFiles();
  const hairpipe::Asset asset = loadCharacter(f);
  const auto info = asset.character();
  ASSERT_TRUE(info.ok()) << info.message();
  EXPECT_EQ(info.value().vertices, 561u);
  EXPECT_EQ(info.value().jointNames, (std::vector<std::string>{"neck", "head"}));
  EXPECT_EQ(info.value().clipNames, (std::vector<std::string>{"nod"}));
  EXPECT_EQ(info.value().farRoots, 0u);
  EXPECT_LT(info.value().maxRootDistance, 0.0015f);  // 0.5 mm above the sphere, whose facets sag up to 0.43 mm
  EXPECT_GT(asset.headTriangleCount(), 900u);  // the mesh is the drawn head

  const auto skinning = hairpipe::meshSkinning(asset);
  ASSERT_TRUE(skinning.ok()) << skinning.message();
  ASSERT_EQ(skinning.value().skin.size(), asset.guideCount());
  for (const auto& w : skinning.value().skin) {
    EXPECT_EQ(w.bones[0], 1u);  // every crown root follows the head alone
    EXPECT_FLOAT_EQ(w.weights[0], 1.0f);
  }
  // At rest every bone is the identity; half way through the nod the head bone turns the roots 45 degrees
  // about x around the joint, as the mesh's crown turns.
  const auto rest = hairpipe::meshClipPose(asset, "nod", 0.0f);
  ASSERT_TRUE(rest.ok()) << rest.message();
  for (const auto& m : rest.value())
    for (int i = 0; i < 16; ++i) EXPECT_NEAR(m.m[i], (i % 5 == 0) ? 1.0f : 0.0f, 1e-6f);
  const auto half = hairpipe::meshClipPose(asset, "nod", 0.5f);
  ASSERT_TRUE(half.ok());
  glm::mat4 head;
  std::memcpy(&head[0][0], half.value()[1].m, sizeof head);
  const glm::quat turn = glm::angleAxis(0.78539816f, glm::vec3(1, 0, 0));
  const glm::vec3 pivot(0.0f, 0.05f, 0.0f);
  const auto roots = asset.guideRoots();
  ASSERT_TRUE(roots.ok());
  for (const auto& r : roots.value()) {
    const glm::vec3 root(r.x, r.y, r.z);
    EXPECT_LT(glm::distance(glm::vec3(head * glm::vec4(root, 1.0f)), pivot + turn * (root - pivot)), 1e-6f);
  }
  EXPECT_THAT(meshFailureOf(hairpipe::meshClipPose(asset, "walk", 0.0f)), HasSubstr("no animation 'walk' (it has 'nod')"));
  std::filesystem::remove_all(f.dir);
}

TEST(CharacterApi, BadMeshesAndAssetsWithoutOneFailByMessage) {
  const Files f = writeFiles();
  hairpipe::AssetSource source;
  source.path = f.hair.string();
  source.mesh = "body.fbx";
  EXPECT_THAT(meshFailureOf(hairpipe::loadAsset(source)), HasSubstr("expected a path ending in .obj, .ply, .gltf, .glb or .tfxmesh"));
  source.mesh = (f.dir / "missing.glb").string();
  EXPECT_THAT(meshFailureOf(hairpipe::loadAsset(source)), HasSubstr("missing.glb"));
  source.mesh = f.mesh.string();
  source.meshCell = -1.0f;
  EXPECT_THAT(meshFailureOf(hairpipe::loadAsset(source)), HasSubstr("meshCell"));
  const auto plain = hairpipe::defaultHeadAsset({hairpipe::Density::Mode::Total, 8, 200, 7});
  ASSERT_TRUE(plain.ok());
  EXPECT_THAT(meshFailureOf(plain.value().character()), HasSubstr("without a character mesh"));
  EXPECT_THAT(meshFailureOf(hairpipe::meshSkinning(plain.value())), HasSubstr("has no skinned character mesh"));
  std::filesystem::remove_all(f.dir);
}

// An instance takes the mesh's skinning as its scalp input and the clip's pose as its bones and its mesh's
// pose, under validation; a pose of the wrong size is refused by message.
TEST(CharacterApi, AnInstanceTakesTheMeshSkinningAsBones) {
  const Files f = writeFiles();
  const hairpipe::Asset asset = loadCharacter(f);
  hairpipe::HeadlessOptions o;
  o.validation = true;
  auto ctx = hairpipe::Context::createHeadless(o);
  ASSERT_TRUE(ctx.ok()) << ctx.message();
  {
    auto renderer = hairpipe::Renderer::create(ctx.value(), {});
    ASSERT_TRUE(renderer.ok()) << renderer.message();
    hairpipe::InstanceSettings s;
    const auto skinning = hairpipe::meshSkinning(asset);
    ASSERT_TRUE(skinning.ok());
    s.scalp.kind = hairpipe::ScalpInput::Kind::Bones;
    s.scalp.skin = skinning.value().skin;
    s.scalp.boneCount = std::uint32_t(skinning.value().boneNames.size());
    auto instance = renderer.value().createInstance(asset, s);
    ASSERT_TRUE(instance.ok()) << instance.message();
    const auto pose = hairpipe::meshClipPose(asset, "nod", 0.25f);
    ASSERT_TRUE(pose.ok());
    EXPECT_TRUE(instance.value().setBones(pose.value()).ok());
    EXPECT_TRUE(instance.value().setMeshPose(pose.value()).ok());
    EXPECT_THAT(meshFailureOf(instance.value().setMeshPose(std::span(pose.value()).first(1))),
                HasSubstr("1 bone matrices for a skeleton of 2"));
  }
  EXPECT_TRUE(ctx.value().waitIdle().ok());
  const auto messages = ctx.value().validationMessages();
  ASSERT_TRUE(messages.ok());
  EXPECT_TRUE(messages.value().empty());
  std::filesystem::remove_all(f.dir);
}
