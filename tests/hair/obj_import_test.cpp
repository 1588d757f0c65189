// OBJ scalp import: the committed fixture, options, and every refused input with its message.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "engine/core/hair/obj_import.h"
#include "tests/hair/hair_test_util.h"

namespace hp {
namespace {
const std::filesystem::path kCap = std::filesystem::path(HAIRPIPE_TEST_DATA_DIR) / "scalp_cap.obj";

std::string loadError(const std::string& objText) {
  test::TempDir dir;
  auto path = dir / "bad.obj";
  test::writeText(path, objText);
  return test::errorOf([&] { loadObjScalp(path); });
}

TEST(ObjImport, LoadsTheCapFixtureWithOutwardNormals) {
  ScalpMesh m = loadObjScalp(kCap);
  EXPECT_EQ(m.vertexCount(), 49u);
  EXPECT_EQ(m.triangles.size(), 12u + 36u * 2u);  // pole fan + fan-split quads
  for (std::uint32_t i = 0; i < m.vertexCount(); ++i)
    EXPECT_GT(glm::dot(m.normals[i], glm::normalize(m.positions[i])), 0.95f) << "vertex " << i;
}

TEST(ObjImport, AppliesScaleAndZUp) {
  test::TempDir dir;
  test::writeText(dir / "z.obj", "v 0 0 100\nv 100 0 100\nv 0 100 100\nf 1 2 3\n");
  ModelTransform t;
  t.scale = 0.01f;
  t.up = UpAxis::Z;
  ScalpMesh m = loadObjScalp(dir / "z.obj", t);
  EXPECT_NEAR(m.positions[0].y, 1.0f, 1e-6f);  // model Z became Y
  EXPECT_NEAR(m.positions[2].z, -1.0f, 1e-6f); // model Y became -Z
  EXPECT_NEAR(m.normals[0].y, 1.0f, 1e-6f);     // model +Z normal is now up
}

TEST(ObjImport, UsesFileNormalsAndResolvesValidNegativeIndices) {
  test::TempDir dir;
  test::writeText(dir / "n.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf -3//1 -2//1 -1//1\n");
  ScalpMesh m = loadObjScalp(dir / "n.obj");
  ASSERT_EQ(m.triangles.size(), 1u);
  EXPECT_EQ(m.triangles[0], glm::uvec3(0, 1, 2));
  EXPECT_EQ(m.normals[1], glm::vec3(0, 0, 1));
}

TEST(ObjImport, DropsUnusedVerticesAndZeroAreaFaces) {
  test::TempDir dir;
  test::writeText(dir / "d.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 9 9 9\nv 2 0 0\nf 1 2 3\nf 1 2 5\n");
  ScalpMesh m = loadObjScalp(dir / "d.obj");
  EXPECT_EQ(m.vertexCount(), 3u);  // vertex 4 is in no face, vertex 5 only in the dropped one
  EXPECT_EQ(m.triangles.size(), 1u);
  EXPECT_EQ(m.droppedDegenerateTriangles, 1u);
}

TEST(ObjImport, RejectsOutOfRangeIndex) {
  EXPECT_THAT_ERROR_CONTAINS_IMPL(loadError("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n"),
                                  "bad.obj: face 1: vertex index 7 is out of range (the file has 3 vertices)");
}

TEST(ObjImport, RejectsNegativeIndexBeforeTheFirstVertex) {
  EXPECT_THAT_ERROR_CONTAINS_IMPL(loadError("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf -1 -2 -4\n"),
                                  "bad.obj: face 2: negative vertex index points before the first vertex");
}

// A polygon of n vertices on a circle (all coplanar), as "f 1 2 ... n" after its vertices.
std::string polygonObj(int n, const std::string& after = "") {
  std::string text;
  for (int i = 0; i < n; ++i)
    text += "v " + std::to_string(std::cos(6.2831853 * i / n)) + " " + std::to_string(std::sin(6.2831853 * i / n)) + " 0\n";
  text += "f";
  for (int i = 1; i <= n; ++i) text += " " + std::to_string(i);
  return text + "\n" + after;
}

TEST(ObjImport, PolygonsOfUpTo255VerticesAreReadAndLargerOnesRefusedByCount) {
  test::TempDir dir;
  test::writeText(dir / "poly.obj", polygonObj(255));
  EXPECT_EQ(loadObjScalp(dir / "poly.obj").triangles.size(), 253u);  // a fan: n - 2 triangles
  // tinyobjloader keeps the count in one byte: 256 read as 0, 300 as 44 (and the next face shifted).
  EXPECT_THAT_ERROR_CONTAINS_IMPL(loadError(polygonObj(256)),
                                  "bad.obj: face 1 has 256 vertices; at most 255 are supported");
  EXPECT_THAT_ERROR_CONTAINS_IMPL(loadError(polygonObj(300, "f 1 2 3\n")),
                                  "bad.obj: face 1 has 300 vertices; at most 255 are supported");
  EXPECT_THAT_ERROR_CONTAINS_IMPL(loadError("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n" + polygonObj(260).substr(0)),
                                  "face 2 has 260 vertices");
}

TEST(ObjImport, RejectsZeroIndex) {
  EXPECT_THAT_ERROR_CONTAINS_IMPL(loadError("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n"), "bad.obj: ");
}

TEST(ObjImport, RejectsFileWithoutFaces) {
  EXPECT_THAT_ERROR_CONTAINS_IMPL(loadError("v 0 0 0\nv 1 0 0\nv 0 1 0\n"), "bad.obj: no faces");
}

TEST(ObjImport, RejectsNonManifoldEdge) {
  EXPECT_THAT_ERROR_CONTAINS_IMPL(
      loadError("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nf 1 2 3\nf 2 1 4\nf 1 2 5\n"),
      "bad.obj: non-manifold edge between vertices 1 and 2 (shared by more than two faces)");
}

TEST(ObjImport, RejectsFaceRepeatingAVertex) {
  EXPECT_THAT_ERROR_CONTAINS_IMPL(loadError("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 2\n"),
                                  "bad.obj: face 1: degenerate face, vertex 2 appears twice");
}

TEST(ObjImport, RejectsOnlyZeroAreaFaces) {
  EXPECT_THAT_ERROR_CONTAINS_IMPL(loadError("v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n"),
                                  "bad.obj: no non-degenerate triangles");
}

TEST(ObjImport, RejectsMissingFile) {
  EXPECT_ERROR_CONTAINS(loadObjScalp("/nonexistent/scalp.obj"), "/nonexistent/scalp.obj");
}
}  // namespace
}  // namespace hp
