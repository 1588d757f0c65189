// hairLayerThickness (samples/tools/host/sim_stats.h): the guide middles' distance from the head's surface,
// against a sphere whose distances are known, through a moved head; non-finite guides left out.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>
#include <vector>

#include "samples/tools/host/sim_stats.h"

TEST(LayerThickness, MeasuresGuideMiddlesFromTheSurfaceInHeadSpace) {
  const float radius = 0.1f;
  const hp::SdfGrid sdf = hp::sampleField([&](const glm::vec3& p) { return glm::length(p) - radius; },
                                          glm::vec3(-0.25f), glm::vec3(0.25f), 0.005f);
  const glm::mat4 head = glm::translate(glm::mat4(1.0f), glm::vec3(1.0f, 2.0f, 3.0f));
  // Ten guides of three particles; guide g's middle stands 0.01 (g + 1) off the sphere along x (world).
  std::vector<glm::vec4> positions;
  for (int g = 0; g < 10; ++g) {
    const float d = 0.01f * float(g + 1);
    for (int k = 0; k < 3; ++k) positions.push_back(head * glm::vec4(radius + (k == 1 ? d : 0.0f), 0.0f, 0.0f, 1.0f));
  }
  // A broken guide: its middle is not finite, so it is left out.
  positions.push_back(glm::vec4(0.0f));
  positions.push_back(glm::vec4(std::numeric_limits<float>::quiet_NaN()));
  positions.push_back(glm::vec4(0.0f));
  const hp::LayerThickness t = hp::hairLayerThickness(positions, 3, sdf, head);
  EXPECT_EQ(t.guides, 10u);
  EXPECT_NEAR(t.mean, 0.055, 5e-4);  // the mean of 0.01 .. 0.10; trilinear on a 5 mm grid
  EXPECT_NEAR(t.p90, 0.09, 5e-4);    // the 9th of 10
  std::vector<glm::vec4> broken(positions.begin(), positions.begin() + 3);
  broken[1] = glm::vec4(std::numeric_limits<float>::infinity());
  EXPECT_EQ(hp::hairLayerThickness(broken, 3, sdf, head).guides, 0u);
}
