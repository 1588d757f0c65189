// The input contract end to end: TessellatePass reads SimulatePass::positions() directly (vec4 per
// particle, root first) after some animated frames; the smooth guides hit the simulated particles
// exactly and match the double-precision reference of the simulated pose.
#include <gtest/gtest.h>

#include "samples/tools/simulation_driver.h"
#include "samples/tools/strand_dump.h"
#include "engine/core/hair/default_head.h"
#include "engine/vk/submit.h"
#include "tests/compute/strand_reference.h"
#include "tests/support/vk_fixture.h"

using namespace hp;

namespace {
class TessellateSimulatedTest : public hp::test::VulkanTest {};

TEST_F(TessellateSimulatedTest, SmoothGuidesFollowTheSimulatedParticles) {
  DensityOptions density;
  density.totalStrands = 3000;
  HairAsset asset = buildDefaultHeadAsset(defaultHeadGrowth(), density);
  SimulatePass simulate(*ctx, asset, SimulationParams{});
  SimulationDriver driver(*ctx, simulate, HeadAnimation::Nod, assetHeadRadius(asset));
  driver.runFrames(8);

  const std::uint32_t g = simulate.guideCount(), p = simulate.particlesPerGuide();
  compute::StrandBuffers buffers(*ctx, g, p, asset.topology);
  compute::TessellatePass tessellate(*ctx, simulate.positions(), buffers);
  compute::InterpolatePass interpolate(*ctx, buffers);
  vk::submitAndWait(*ctx, [&](VkCommandBuffer cmd) {
    vk::memoryBarrier(*ctx, cmd, vk::BufferUse::ComputeWrite, vk::BufferUse::ComputeRead);  // simulate -> tessellate
    compute::recordStrandPasses(*ctx, cmd, tessellate, interpolate);
  }, "simulated strands");

  GuideSet simulated;
  simulated.particlesPerGuide = p;
  for (const glm::vec4& x : driver.readPositions()) simulated.positions.emplace_back(x);
  compute::StrandData smooth = compute::readSmoothedGuides(*ctx, buffers, vk::BufferUse::ComputeRead);
  std::vector<std::uint32_t> k = test::refParticleVertices(p, 36);
  std::size_t misses = 0;
  for (std::uint32_t guide = 0; guide < g; ++guide)
    for (std::uint32_t i = 0; i < p; ++i)
      misses += glm::vec3(smooth.positions[std::size_t(guide) * 36 + k[i]]) != simulated.guide(guide)[i];
  EXPECT_EQ(misses, 0u);

  test::RefCurves ref = test::refTessellate(simulated, 36);
  const std::vector<double> lengths = test::guideLengths(simulated);
  double worst = 0.0;
  for (std::size_t v = 0; v < ref.positions.size(); ++v)
    worst = std::max(worst, glm::length(glm::dvec3(glm::vec3(smooth.positions[v])) - ref.positions[v]) / lengths[v / 36]);
  EXPECT_LT(worst, 2e-6);
}
}  // namespace (the tests too: their classes derive from the fixtures)
