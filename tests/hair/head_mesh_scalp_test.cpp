#include <gtest/gtest.h>

#include "engine/core/hair/default_head.h"
#include "engine/core/hair/head_mesh.h"

using namespace hp;

TEST(HeadMeshScalp, MarksVerticesUnderTheRootsAndLeavesTheFaceBare) {
  HairAsset asset = buildDefaultHeadAsset();
  const HeadMesh& head = asset.head;
  ASSERT_EQ(head.scalp.size(), head.positions.size());
  // The crown (top of the cranium) is under hair; the lowest vertices (shoulders) are not.
  std::size_t top = 0, bottom = 0, front = 0;
  for (std::size_t i = 0; i < head.positions.size(); ++i) {
    if (head.positions[i].y > head.positions[top].y) top = i;
    if (head.positions[i].y < head.positions[bottom].y) bottom = i;
    if (head.positions[i].z > head.positions[front].z) front = i;
  }
  EXPECT_GT(head.scalp[top], 0.9f);
  EXPECT_EQ(head.scalp[bottom], 0.0f);
  EXPECT_LT(head.scalp[front], 0.1f) << "the face stays bare";
  for (float w : head.scalp) EXPECT_TRUE(w >= 0.0f && w <= 1.0f);
}

TEST(HeadMeshScalp, FewerThanTwoRootsMarkNothing) {
  HeadMesh mesh = makeEllipsoidMesh({0, 0, 0}, {1, 1, 1}, 8, 4);
  std::vector<glm::vec3> roots{{0, 1, 0}};
  markScalp(mesh, roots);
  ASSERT_EQ(mesh.scalp.size(), mesh.positions.size());
  for (float w : mesh.scalp) EXPECT_EQ(w, 0.0f);
}
