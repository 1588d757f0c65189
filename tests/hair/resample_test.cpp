// Resampling imported strands to P particles with root-increasing spacing.
#include <gtest/gtest.h>

#include <cmath>

#include "engine/core/hair/segment_profile.h"
#include "tests/hair/hair_test_util.h"

namespace hp {
namespace {
std::vector<glm::vec3> quarterCircle(int n) {
  std::vector<glm::vec3> p;
  for (int i = 0; i < n; ++i) {
    float a = 1.5707963f * float(i) / float(n - 1);
    p.emplace_back(std::sin(a), std::cos(a), 0.0f);
  }
  return p;
}

TEST(Resample, KeepsRootTipAndArcLength) {
  auto in = quarterCircle(200);
  std::vector<glm::vec3> out(7);
  resamplePolyline(in, 7, 1.3f, out);
  EXPECT_EQ(out.front(), in.front());
  EXPECT_EQ(out.back(), in.back());
  float lin = polylineLength(in), lout = polylineLength(out);
  EXPECT_NEAR(lout / lin, 1.0f, 0.01f) << "input " << lin << " resampled " << lout;
}

TEST(Resample, SpacingGrowsFromRootToTip) {
  auto in = quarterCircle(300);
  std::vector<glm::vec3> out(10);
  resamplePolyline(in, 10, 1.2f, out);
  for (int k = 2; k < 10; ++k)
    EXPECT_GT(glm::length(out[k] - out[k - 1]), glm::length(out[k - 1] - out[k - 2]));
}

TEST(Resample, ExactOnAStraightLineWithUnevenInput) {
  std::vector<glm::vec3> in{{0, 0, 0}, {0, -0.1f, 0}, {0, -0.15f, 0}, {0, -0.9f, 0}, {0, -1, 0}};
  std::vector<glm::vec3> out(4);
  resamplePolyline(in, 4, 2.0f, out);  // segments 1/7, 2/7, 4/7
  EXPECT_NEAR(out[1].y, -1.0f / 7.0f, 1e-6f);
  EXPECT_NEAR(out[2].y, -3.0f / 7.0f, 1e-6f);
  EXPECT_EQ(out[3].y, -1.0f);
}

TEST(Resample, UpsamplesAndHandlesZeroLength) {
  std::vector<glm::vec3> in{{0, 0, 0}, {1, 0, 0}};
  std::vector<glm::vec3> out(64);
  resamplePolyline(in, 64, 1.0f, out);
  EXPECT_NEAR(out[32].x, 32.0f / 63.0f, 1e-6f);
  std::vector<glm::vec3> still{{1, 2, 3}, {1, 2, 3}};
  resamplePolyline(still, 64, 1.3f, out);
  for (const auto& p : out) EXPECT_EQ(p, glm::vec3(1, 2, 3));
}

TEST(Resample, RejectsTooFewPoints) {
  std::vector<glm::vec3> in{{0, 0, 0}}, out(7);
  EXPECT_ERROR_CONTAINS(resamplePolyline(in, 7, 1.3f, out), "need >= 2 input points");
}
}  // namespace
}  // namespace hp
