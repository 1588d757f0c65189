// Character meshes (issue 29; docs/THEORY.md §8.4-8.6): a skinned glTF made here loads its joints, weights
// and clips; rotating a bone moves the roots bound to the mesh exactly with it; .tfxmesh and PLY files read
// their counts and values; hostile files are refused by message.
#include <gtest/gtest.h>

#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <cstring>

#include "engine/core/hair/gltf_mesh.h"
#include "engine/core/hair/mesh_file.h"
#include "engine/core/hair/ply_file.h"
#include "engine/core/hair/root_binding.h"
#include "engine/core/hair/sdf_mesh.h"
#include "engine/core/hair/skeleton_pose.h"
#include "engine/core/hair/tfx_mesh_file.h"
#include "tests/hair/gltf_test_file.h"
#include "tests/hair/hair_test_util.h"

namespace hp {
namespace {
constexpr float kRadius = 0.09f;
constexpr float kNeckY = 0.05f;  // the "head" joint sits here; vertices above 0.03 follow it alone

// A 9 cm sphere skinned to a "neck" joint at the centre and a "head" joint above it, with a clip "nod" that
// turns the head 90 degrees about x in one second.
test::GltfTestMesh skinnedSphere() {
  test::GltfTestMesh m = test::uvSphere(kRadius);
  m.joints = {{"neck", -1, glm::vec3(0.0f)}, {"head", 0, glm::vec3(0.0f, kNeckY, 0.0f)}};
  for (const glm::vec3& p : m.positions) {
    const bool head = p.y > 0.03f;
    m.vertexJoints.emplace_back(head ? 1 : 0, 0, 0, 0);
    m.vertexWeights.emplace_back(1.0f, 0.0f, 0.0f, 0.0f);
  }
  const glm::quat turned = glm::angleAxis(glm::radians(90.0f), glm::vec3(1.0f, 0.0f, 0.0f));
  m.clips.push_back({"nod", 1, {0.0f, 1.0f}, {glm::quat(1.0f, 0.0f, 0.0f, 0.0f), turned}});
  return m;
}

CharacterMesh loadGlb(const test::GltfTestMesh& m, const ModelTransform& transform = {}) {
  return parseGltf(test::glbBytes(m), "test.glb", {}, transform);
}

// `text` with the first `from` replaced by `to` (a corruption for the refusal tests).
std::string replaced(std::string text, const std::string& from, const std::string& to) {
  text.replace(text.find(from), from.size(), to);
  return text;
}

std::uint32_t jointNamed(const CharacterMesh& m, const std::string& name) {
  for (std::size_t j = 0; j < m.skeleton.size(); ++j)
    if (m.skeleton[j].name == name) return std::uint32_t(j);
  ADD_FAILURE() << "no joint " << name;
  return 0;
}

// Roots on the crown: 40 points of a cap 1 mm above the sphere (all on vertices weighted to the head).
std::vector<glm::vec3> crownRoots(float scale) {
  std::vector<glm::vec3> roots;
  for (int i = 0; i < 40; ++i) {
    const float a = 0.7f * float(i), up = 0.25f + 0.01f * float(i % 7);
    roots.push_back(scale * (kRadius + 0.001f) * glm::normalize(glm::vec3(std::sin(a) * up, 1.0f, std::cos(a) * up)));
  }
  return roots;
}
}  // namespace

TEST(CharacterMesh, ASkinnedGlbLoadsItsJointsWeightsAndClips) {
  const test::GltfTestMesh source = skinnedSphere();
  const CharacterMesh m = loadGlb(source);
  EXPECT_EQ(m.vertexCount(), source.positions.size());
  EXPECT_EQ(m.triangleCount(), source.indices.size() / 3);
  ASSERT_EQ(m.skeleton.size(), 2u);
  EXPECT_EQ(m.skeleton[0].name, "neck");
  EXPECT_EQ(m.skeleton[0].parent, -1);
  EXPECT_EQ(m.skeleton[1].name, "head");
  EXPECT_EQ(m.skeleton[1].parent, 0);
  ASSERT_TRUE(m.skinned());
  for (std::size_t v = 0; v < m.positions.size(); ++v) {
    EXPECT_EQ(m.joints[v].x, source.positions[v].y > 0.03f ? 1u : 0u) << v;
    EXPECT_FLOAT_EQ(m.weights[v].x, 1.0f);
  }
  ASSERT_EQ(m.animations.size(), 1u);
  EXPECT_EQ(m.animations[0].name, "nod");
  EXPECT_FLOAT_EQ(m.animations[0].duration, 1.0f);
  // The rest pose moves nothing: every skinning matrix is the identity.
  for (const glm::mat4& s : skinningMatrices(m, restPose(m)))
    for (int c = 0; c < 4; ++c) EXPECT_LT(glm::length(s[c] - glm::mat4(1.0f)[c]), 1e-6f);
  EXPECT_ERROR_CONTAINS(findClip(m, "walk"), "it has 'nod'");
}

// The roots bind to the sphere within float rounding; the clip turns the head joint 60 degrees at 2/3 s, and
// the roots rebuilt on the skinned mesh sit where the same rotation about the joint takes them (under 1e-5 m),
// as do the mesh's head vertices. In centimetres (scale 0.01) the same holds in head space.
TEST(CharacterMesh, RotatingABoneMovesTheBoundRootsExactly) {
  for (const float unitsPerMetre : {1.0f, 100.0f}) {
    ModelTransform transform;
    transform.scale = 1.0f / unitsPerMetre;
    test::GltfTestMesh source = skinnedSphere();
    for (auto& p : source.positions) p *= unitsPerMetre;
    for (auto& j : source.joints) j.translation *= unitsPerMetre;
    const CharacterMesh m = loadGlb(source, transform);
    const std::vector<glm::vec3> roots = crownRoots(1.0f);
    const RootBindings b = bindRoots(roots, m.positions, m.triangles, 0.01f);
    EXPECT_EQ(b.farRoots, 0u);
    EXPECT_LT(b.maxDistance, 0.0015f);  // 1 mm above the sphere, whose facets sag up to 0.43 mm inside it
    for (std::size_t r = 0; r < roots.size(); ++r)
      EXPECT_LT(glm::distance(boundRootPosition(b.roots[r], m.positions, m.triangles), roots[r]), 1e-6f) << r;

    const auto pose = samplePose(m, findClip(m, "nod"), 2.0f / 3.0f);
    const SkinnedVertices skinned = skinMesh(m, skinningMatrices(m, pose));
    const glm::quat turn = glm::angleAxis(glm::radians(60.0f), glm::vec3(1.0f, 0.0f, 0.0f));
    const glm::vec3 pivot(0.0f, kNeckY, 0.0f);
    double worst = 0.0;
    for (std::size_t r = 0; r < roots.size(); ++r) {
      const glm::vec3 moved = boundRootPosition(b.roots[r], skinned.positions, m.triangles);
      worst = std::max(worst, double(glm::distance(moved, pivot + turn * (roots[r] - pivot))));
    }
    for (std::size_t v = 0; v < m.positions.size(); ++v)
      if (source.positions[v].y > 0.03f * unitsPerMetre)
        worst = std::max(worst, double(glm::distance(skinned.positions[v], pivot + turn * (m.positions[v] - pivot))));
    std::cout << "units per metre " << unitsPerMetre << ": worst root or head vertex error " << worst << " m\n";
    EXPECT_LT(worst, 1e-5);
    // Every crown root follows the head joint alone.
    for (const auto& w : boundRootSkin(b, m)) {
      EXPECT_EQ(w.bones.x, jointNamed(m, "head"));
      EXPECT_FLOAT_EQ(w.weights.x, 1.0f);
    }
  }
}

// The nearest triangle is the one a brute-force search finds (distances equal), roots far from the mesh are
// counted, and a root's offset is signed: outside positive.
TEST(CharacterMesh, RootsBindToTheirNearestTriangle) {
  const CharacterMesh m = loadGlb(test::uvSphere(kRadius, 24, 12));
  std::vector<glm::vec3> roots;
  for (int i = 0; i < 200; ++i) {
    const float a = 0.37f * float(i), h = -1.0f + 2.0f * float(i) / 199.0f, rr = std::sqrt(1.0f - h * h);
    const float radius = kRadius * (0.8f + 0.5f * float(i % 5) / 4.0f);  // inside to 1.3x outside
    roots.push_back(radius * glm::vec3(rr * std::sin(a), h, rr * std::cos(a)));
  }
  const RootBindings b = bindRoots(roots, m.positions, m.triangles, 0.01f);
  std::uint32_t far = 0;
  for (std::size_t r = 0; r < roots.size(); ++r) {
    float best = 1e30f;
    for (const glm::uvec3& t : m.triangles) {
      const glm::vec3 a = m.positions[t.x], bb = m.positions[t.y], c = m.positions[t.z];
      best = std::min(best, pointTriangleDistance(roots[r], a, bb, c));
    }
    EXPECT_NEAR(b.roots[r].distance, best, 1e-6f) << r;
    far += best > 0.01f ? 1u : 0u;
    EXPECT_EQ(b.roots[r].offset > 0.0f, glm::length(roots[r]) > kRadius) << r;
    EXPECT_LT(glm::distance(boundRootPosition(b.roots[r], m.positions, m.triangles), roots[r]), 1e-6f) << r;
  }
  EXPECT_EQ(b.farRoots, far);
  EXPECT_GT(far, 0u);
}

TEST(CharacterMesh, ATfxMeshReadsItsCountsAndValues) {
  const std::string text =
      "# TressFX collision mesh\nnumOfBones 2\n# index name\n0 Root_JNT\n1 Head_JNT\nnumOfVertices 3\n"
      "0 0 0 0 0 0 1 0 0 0 0 1 0 0 0\n1 1 0 0 0 0 1 1 0 0 0 0.25 0.75 0 0\n2 0 1 0 0 0 1 1 0 0 0 2 0 0 0\n"
      "numOfTriangles 1\n0 0 1 2\n";
  ModelTransform cm;
  cm.scale = 0.01f;
  const CharacterMesh m = parseTfxMesh(text, "t.tfxmesh", cm);
  ASSERT_EQ(m.vertexCount(), 3u);
  ASSERT_EQ(m.triangleCount(), 1u);
  EXPECT_EQ(m.skeleton[1].name, "Head_JNT");
  EXPECT_FLOAT_EQ(m.positions[1].x, 0.01f);
  EXPECT_EQ(m.joints[1], glm::uvec4(1, 0, 0, 0));
  EXPECT_FLOAT_EQ(m.weights[1].y, 0.75f);
  EXPECT_FLOAT_EQ(m.weights[2].x, 1.0f);  // normalised from 2
  EXPECT_FLOAT_EQ(m.normals[0].z, 1.0f);
  // Corruptions, each named.
  auto corrupt = [&](const std::string& from, const std::string& to) { return replaced(text, from, to); };
  EXPECT_ERROR_CONTAINS(parseTfxMesh(corrupt("numOfVertices 3", "numOfVertices 300000000"), "t"), "more than the file holds");
  EXPECT_ERROR_CONTAINS(parseTfxMesh(corrupt("1 0 0 0 0.25", "7 0 0 0 0.25"), "t"), "is not a bone");
  EXPECT_ERROR_CONTAINS(parseTfxMesh(corrupt("0 0 1 2\n", "0 0 1 9\n"), "t"), "refers to vertex 9");
  EXPECT_ERROR_CONTAINS(parseTfxMesh(corrupt("1 1 0 0", "1 nan 0 0"), "t"), "not finite");
  EXPECT_ERROR_CONTAINS(parseTfxMesh(corrupt("1 1 0 0", "1 x 0 0"), "t"), "is not a number");
  EXPECT_ERROR_CONTAINS(parseTfxMesh(corrupt("2 0 1 0 0 0 1 1 0 0 0 2 0 0 0", "2 0 1 0 0 0 1 1 0 0 0 0 0 0 0"), "t"), "sum to 0");
  EXPECT_ERROR_CONTAINS(parseTfxMesh(corrupt("numOfBones", "bones"), "t"), "expected 'numOfBones'");
  EXPECT_ERROR_CONTAINS(parseTfxMesh(text.substr(0, text.size() - 8), "t"), "numOfTriangles 1 is negative or more than");
  EXPECT_ERROR_CONTAINS(parseTfxMesh(corrupt("0 0 1 2\n", "0 0 100\n"), "t"), "triangle 0 needs 4 fields");
}

namespace {
std::vector<std::byte> textBytes(const std::string& s) {
  return {reinterpret_cast<const std::byte*>(s.data()), reinterpret_cast<const std::byte*>(s.data()) + s.size()};
}

// A binary PLY of a unit quad (two triangles by one 4-corner face) in the given byte order, with an extra
// per-vertex "confidence" and an extra element the reader skips.
std::vector<std::byte> binaryQuad(bool big) {
  std::string header = std::string("ply\nformat ") + (big ? "binary_big_endian" : "binary_little_endian") +
                       " 1.0\ncomment test\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                       "property uchar confidence\nelement face 1\nproperty list uchar int vertex_indices\n"
                       "element extra 1\nproperty list uchar ushort values\nend_header\n";
  std::vector<std::byte> out = textBytes(header);
  auto put = [&](const void* p, std::size_t n) {
    std::vector<std::byte> b(static_cast<const std::byte*>(p), static_cast<const std::byte*>(p) + n);
    if (big) std::reverse(b.begin(), b.end());
    out.insert(out.end(), b.begin(), b.end());
  };
  const float corners[4][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  for (const auto& c : corners) {
    for (float f : c) put(&f, 4);
    const std::uint8_t confidence = 200;
    put(&confidence, 1);
  }
  const std::uint8_t n = 4, two = 2;
  put(&n, 1);
  for (std::int32_t i : {0, 1, 2, 3}) put(&i, 4);
  put(&two, 1);
  for (std::uint16_t v : {std::uint16_t(7), std::uint16_t(8)}) put(&v, 2);
  return out;
}
}  // namespace

TEST(CharacterMesh, PlyFilesReadInEveryFormat) {
  const std::string ascii =
      "ply\nformat ascii 1.0\nelement vertex 4\nproperty double x\nproperty double y\nproperty double z\n"
      "property float nx\nproperty float ny\nproperty float nz\nelement face 1\n"
      "property list uchar uint vertex_index\nend_header\n"
      "0 0 0 0 0 2\n1 0 0 0 0 1\n1 1 0 0 0 1\n0 1 0 0 0 1\n4 0 1 2 3\n";
  for (const auto& [name, data] : {std::pair{"ascii", textBytes(ascii)}, std::pair{"little", binaryQuad(false)},
                                   std::pair{"big", binaryQuad(true)}}) {
    SCOPED_TRACE(name);
    const CharacterMesh m = parsePly(data, "quad.ply");
    ASSERT_EQ(m.vertexCount(), 4u);
    ASSERT_EQ(m.triangleCount(), 2u);
    EXPECT_EQ(m.triangles[1], glm::uvec3(0, 2, 3));
    EXPECT_FLOAT_EQ(m.positions[2].y, 1.0f);
    EXPECT_FLOAT_EQ(m.normals[0].z, 1.0f);
    EXPECT_FALSE(m.skinned());
  }
  auto corrupt = [&](const std::string& from, const std::string& to) { return textBytes(replaced(ascii, from, to)); };
  EXPECT_ERROR_CONTAINS(parsePly(corrupt("element vertex 4", "element vertex 4000000000"), "q"), "more than the file holds");
  EXPECT_ERROR_CONTAINS(parsePly(corrupt("4 0 1 2 3", "4 0 1 2 4"), "q"), "refers to vertex 4");
  EXPECT_ERROR_CONTAINS(parsePly(corrupt("4 0 1 2 3", "2 0 1 2 3"), "q"), "outside 3..1024");
  // Indices of a float type: only whole numbers name a vertex (NaN became vertex 0, 1.7 vertex 1).
  const auto floatIndices = [&](const std::string& face) {
    return textBytes(replaced(replaced(ascii, "list uchar uint", "list uchar float"), "4 0 1 2 3", face));
  };
  EXPECT_EQ(parsePly(floatIndices("4 0 1 2 3"), "f").triangleCount(), 2u);
  EXPECT_ERROR_CONTAINS(parsePly(floatIndices("4 0 nan 2 3"), "f"), "refers to vertex NaN");
  EXPECT_ERROR_CONTAINS(parsePly(floatIndices("4 0 1.7 2 3"), "f"), "refers to vertex 1.7");
  EXPECT_ERROR_CONTAINS(parsePly(textBytes(replaced(ascii, "list uchar uint", "list float uint")), "f"),
                        "a list counted by a float");
  EXPECT_ERROR_CONTAINS(parsePly(corrupt("1 1 0 0 0 1", "1 inf 0 0 0 1"), "q"), "not finite");
  EXPECT_ERROR_CONTAINS(parsePly(corrupt("format ascii", "format utf8"), "q"), "unknown format");
  EXPECT_ERROR_CONTAINS(parsePly(corrupt("end_header", "end_head"), "q"), "unknown header line");
  EXPECT_ERROR_CONTAINS(parsePly(textBytes("ply\nformat ascii 1.0\nelement vertex 1\n"), "q"), "no 'end_header'");
  std::vector<std::byte> cut = binaryQuad(false);
  cut.resize(cut.size() - 3);
  EXPECT_ERROR_CONTAINS(parsePly(cut, "q"), "ends before");
}

TEST(CharacterMesh, HostileGlbFilesAreRefusedByMessage) {
  const std::vector<std::byte> good = test::glbBytes(skinnedSphere());
  std::vector<std::byte> cut(good.begin(), good.begin() + std::ptrdiff_t(good.size() / 2));
  EXPECT_ERROR_CONTAINS(parseGltf(cut, "t.glb", {}), "t.glb: not a glTF hairpipe can read");
  // An index past the vertices.
  test::GltfTestMesh bad = skinnedSphere();
  bad.indices[5] = 100000;
  EXPECT_ERROR_CONTAINS(parseGltf(test::glbBytes(bad), "t.glb", {}), "is past its");
  // A joint weighted that the skin does not have.
  bad = skinnedSphere();
  bad.vertexJoints[3].x = 9;
  EXPECT_ERROR_CONTAINS(parseGltf(test::glbBytes(bad), "t.glb", {}), "is past the skeleton");
  // NaN weights.
  bad = skinnedSphere();
  bad.vertexWeights[2].x = NAN;
  EXPECT_ERROR_CONTAINS(parseGltf(test::glbBytes(bad), "t.glb", {}), "not finite");
  // A .gltf whose buffer lies outside its folder, and one whose accessor reaches past its buffer.
  const std::string outside = R"({"asset":{"version":"2.0"},"buffers":[{"uri":"../../etc/passwd","byteLength":12}]})";
  test::TempDir dir;
  EXPECT_ERROR_CONTAINS(parseGltf(textBytes(outside), "o.gltf", dir.path()), "outside the glTF's folder");
  const std::string past =
      R"({"asset":{"version":"2.0"},"scene":0,"scenes":[{"nodes":[0]}],"nodes":[{"mesh":0}],)"
      R"("meshes":[{"primitives":[{"attributes":{"POSITION":0}}]}],)"
      R"("accessors":[{"bufferView":0,"componentType":5126,"count":4,"type":"VEC3"}],)"
      R"("bufferViews":[{"buffer":0,"byteLength":36}],)"
      R"("buffers":[{"uri":"data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA","byteLength":36}]})";
  EXPECT_ERROR_CONTAINS(parseGltf(textBytes(past), "p.gltf", {}), "reaches past its buffer view");
  // A node that is its own grandchild.
  const std::string cycle =
      R"({"asset":{"version":"2.0"},"nodes":[{"children":[1]},{"children":[0]}]})";
  EXPECT_ERROR_CONTAINS(parseGltf(textBytes(cycle), "c.gltf", {}), "on a cycle of nodes");
  EXPECT_ERROR_CONTAINS(loadCharacterMesh(dir / "body.fbx"), "not a mesh hairpipe reads");
}

// A character mesh placed past 10 km by its scale is refused as such (it was "vertex N is not finite" or "no
// non-degenerate triangles" once the degenerate test squared its distances), in every format.
TEST(CharacterMesh, AMeshScaledPastHeadSpaceIsRefusedAsSuch) {
  test::TempDir dir;
  test::writeText(dir / "tri.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                   "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                                   "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  ModelTransform far;
  far.scale = 1e30f;
  EXPECT_ERROR_CONTAINS(loadCharacterMesh(dir / "tri.ply", far), "tri.ply: point 1 lies at (1e+30, 0, 0)");
  EXPECT_EQ(loadCharacterMesh(dir / "tri.ply").triangleCount(), 1u);
}
}  // namespace hp
