// ScalpMesh construction: computed normals, degenerate triangles dropped and counted, bad input.
#include <gtest/gtest.h>

#include "engine/core/hair/scalp_mesh.h"
#include "tests/hair/hair_test_util.h"

namespace hp {
namespace {
TEST(HairScalpMesh, ComputesAreaWeightedUnitNormals) {
  // A pyramid without its base: the apex averages four equal faces, a corner two of them.
  std::vector<glm::vec3> p{{0, 1, 0}, {1, 0, 1}, {1, 0, -1}, {-1, 0, -1}, {-1, 0, 1}};
  ScalpMesh m = buildScalpMesh(p, {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}, {0, 4, 1}});
  ASSERT_EQ(m.normals.size(), 5u);
  for (const auto& n : m.normals) EXPECT_NEAR(glm::length(n), 1.0f, 1e-6f);
  EXPECT_NEAR(glm::distance(m.normals[0], glm::vec3(0, 1, 0)), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::distance(m.normals[1], glm::normalize(glm::vec3(1, 1, 0) + glm::vec3(0, 1, 1))), 0.0f, 1e-6f);
  EXPECT_EQ(m.droppedDegenerateTriangles, 0u);
}

TEST(HairScalpMesh, KeepsGivenNormalsNormalized) {
  ScalpMesh m = buildScalpMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}}, {{0, 0, 2}, {0, 3, 0}, {4, 0, 0}});
  EXPECT_EQ(m.normals[0], glm::vec3(0, 0, 1));
  EXPECT_EQ(m.normals[1], glm::vec3(0, 1, 0));
  EXPECT_EQ(m.normals[2], glm::vec3(1, 0, 0));
}

TEST(HairScalpMesh, DropsAndCountsDegenerateTriangles) {
  std::vector<glm::vec3> p{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}};
  // Triangle 1 is collinear (zero area), triangle 2 repeats a vertex.
  ScalpMesh m = buildScalpMesh(p, {{0, 1, 2}, {0, 1, 3}, {0, 2, 2}, {1, 3, 2}});
  EXPECT_EQ(m.triangles.size(), 2u);
  EXPECT_EQ(m.droppedDegenerateTriangles, 2u);
}

TEST(HairScalpMesh, RejectsBadInput) {
  std::vector<glm::vec3> p{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  EXPECT_ERROR_CONTAINS(buildScalpMesh(p, {{0, 1, 3}}, {}, "s.obj"),
                        "s.obj: triangle 0 refers to vertex 3 but there are only 3");
  EXPECT_ERROR_CONTAINS(buildScalpMesh(p, {{0, 1, 1}}, {}, "s.obj"), "s.obj: no non-degenerate triangles");
  EXPECT_ERROR_CONTAINS(buildScalpMesh({{0, 0, 0}, {1, 0, 0}, {0, NAN, 0}}, {{0, 1, 2}}, {}, "s.obj"),
                        "s.obj: vertex 2 is not finite");
  EXPECT_ERROR_CONTAINS(buildScalpMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {5, 5, 5}}, {{0, 1, 2}}, {}, "s.obj"),
                        "s.obj: vertex 3 has no usable normal");
  EXPECT_ERROR_CONTAINS(buildScalpMesh(p, {{0, 1, 2}}, {{0, 0, 1}}, "s.obj"), "1 normals for 3 vertices");
}
}  // namespace
}  // namespace hp
