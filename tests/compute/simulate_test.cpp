// The guide simulation on the device: against the double-precision CPU reference, and the invariants
// the issue asks for (lengths, clearance of spheres and of the head's distance field, no NaN under
// violent motion, teleport, energy decay).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "samples/tools/simulation_driver.h"
#include "engine/core/error.h"
#include "engine/core/hair/default_head.h"
#include "engine/core/hair/head_sdf.h"
#include "engine/core/hair/sdf_grid.h"
#include "tests/compute/sim_reference.h"
#include "tests/support/thinned_head.h"
#include "tests/support/vk_fixture.h"

using namespace hp;
using hp::test::thinnedDefaultHead;
using hp::test::VulkanTest;

namespace {
double maxDifference(const std::vector<glm::vec4>& gpu, const std::vector<glm::dvec3>& cpu) {
  double worst = 0.0;
  for (std::size_t i = 0; i < gpu.size(); ++i) worst = std::max(worst, glm::length(glm::dvec3(gpu[i]) - cpu[i]));
  return worst;
}

struct Compared {
  double maxDifference;  // max |gpu - cpu| over the particles (metres)
  double moved;          // how far particle 6 moved from its rest position on the device
};
// 100 frames of nodding of a thinned default head on the device and in the CPU reference, the hair grid off
// (the reference has none).
Compared againstReference(const vk::Context& ctx, const SimulationParams& withGrid) {
  const SimulationParams params = hp::test::withoutGrid(withGrid);
  HairAsset asset = thinnedDefaultHead(16);
  SimulatePass pass(ctx, asset, params);
  SimulationDriver driver(ctx, pass, HeadAnimation::Nod, assetHeadRadius(asset));
  hp::test::SimReference reference(pass, params, glm::mat4(1.0f));
  for (int f = 0; f < 100; ++f) {
    reference.step(driver.nextMotion());
    driver.runFrames(1);
  }
  const std::vector<glm::vec4> gpu = driver.readPositions();
  return {maxDifference(gpu, reference.positions()), glm::length(glm::dvec3(gpu[6]) - glm::dvec3(pass.rest()[6]))};
}
}  // namespace

TEST_F(VulkanTest, SimulationMatchesTheCpuReferenceOverOneHundredFramesOfNodding) {
  SimulationParams params;
  params.windStrength = 2.0;  // exercise the wind and gust terms too
  params.windGust = 0.5;
  const Compared c = againstReference(*ctx, params);
  // Float vs double through 100 frames x 2 substeps x 8 iterations: 50 micrometres on ~40 cm hair.
  EXPECT_LT(c.maxDifference, 5e-5) << "max |gpu - cpu| in metres";
  EXPECT_GT(c.moved, 1e-3) << "the hair should have moved, or this comparison proves nothing";
}

TEST_F(VulkanTest, SettledHairKeepsSegmentLengthsWithinOnePercent) {
  HairAsset asset = thinnedDefaultHead(4);
  SimulatePass pass(*ctx, asset, SimulationParams{});
  SimulationDriver driver(*ctx, pass, HeadAnimation::None, assetHeadRadius(asset));
  driver.runFrames(180);
  SimStats s = driver.stats();
  EXPECT_LT(s.maxLengthError, 0.01);
  EXPECT_EQ(s.nanCount, 0u);
  EXPECT_LT(s.maxSpeed, 0.05) << "settled hair should be nearly still";
}

TEST_F(VulkanTest, PearlsStayOutsideTheCollidersEveryFrameOfAShake) {
  HairAsset asset = thinnedDefaultHead(8);
  SimulatePass pass(*ctx, asset, SimulationParams{});
  const float radius = assetHeadRadius(asset);
  SimulationDriver driver(*ctx, pass, HeadAnimation::Shake, radius);
  double worst = 1e9;
  for (int f = 0; f < 120; ++f) {
    driver.runFrames(1);
    worst = std::min(worst, driver.stats().minColliderClearance);
  }
  EXPECT_GE(worst, -1e-4 * radius);
}

// Hair never ends inside the head: through 600 frames of each motion, every free particle (read back
// every 50 frames, taken to head space) is outside the analytic head field, within 0.1 mm.
TEST_F(VulkanTest, PearlsStayOutsideTheHeadFieldThroughSixHundredFramesOfShakeNodAndTurn) {
  HairAsset asset = thinnedDefaultHead(8);
  asset.colliders.clear();  // the field alone
  for (HeadAnimation animation : {HeadAnimation::Shake, HeadAnimation::Nod, HeadAnimation::Turn}) {
    SimulatePass pass(*ctx, asset, SimulationParams{});
    SimulationDriver driver(*ctx, pass, animation, assetHeadRadius(asset));
    double worst = 1e9;
    for (int chunk = 0; chunk < 12; ++chunk) {
      driver.runFrames(50);
      const glm::mat4 toHead = glm::inverse(driver.head());
      const auto positions = driver.readPositions();
      for (std::size_t i = 0; i < positions.size(); ++i)
        if (i % pass.particlesPerGuide() != 0)
          worst = std::min(worst, double(headDistance(glm::vec3(toHead * glm::vec4(glm::vec3(positions[i]), 1.0f)))));
    }
    EXPECT_GE(worst, -1e-4) << headAnimationName(animation) << ": deepest particle inside the head (m)";
  }
}

// A horizontal slab 1.5 cells thick across the hanging hair, its middle halfway between two node planes: the
// nodes on both faces of the middle cell are equal, so the interpolant is flat across that cell and its own
// gradient shows no way out. After one frame every free particle has left it anyway, on the device and in the CPU
// reference (the push takes central differences where the gradient is flat: shaders/shared/sdf.h SDF_FLAT_GRADIENT).
TEST_F(VulkanTest, PearlsLeaveASlabThinnerThanTwoCellsWhoseMiddleIsMidCell) {
  HairAsset asset = thinnedDefaultHead(16);
  asset.colliders.clear();
  const std::uint32_t n = asset.guides.particlesPerGuide;
  std::vector<float> middles;
  glm::vec3 lo(1e9f), hi(-1e9f);
  for (std::uint32_t g = 0; g < asset.guides.guideCount(); ++g) {
    middles.push_back(asset.guides.guide(g)[n / 2].y);
    for (const glm::vec3& p : asset.guides.guide(g)) lo = glm::min(lo, p), hi = glm::max(hi, p);
  }
  std::nth_element(middles.begin(), middles.begin() + std::ptrdiff_t(middles.size() / 2), middles.end());
  lo -= glm::vec3(0.1f);
  hi += glm::vec3(0.1f);
  const float cell = 0.01f;
  const float originY = gridCovering(lo, hi, cell).origin.y;
  const float y0 = originY + (std::floor((middles[middles.size() / 2] - originY) / cell) + 0.5f) * cell;
  auto slab = [&](const glm::vec3& p) { return std::abs(p.y - y0) - 0.75f * cell; };
  asset.sdf = std::make_shared<const SdfGrid>(sampleField(slab, lo, hi, cell));
  std::size_t inMiddleCell = 0;
  for (std::size_t i = 0; i < asset.guides.positions.size(); ++i)
    inMiddleCell += i % n != 0 && std::abs(asset.guides.positions[i].y - y0) < 0.5f * cell;
  ASSERT_GE(inMiddleCell, 3u) << "the slab must hold particles where the interpolant is flat, or this proves nothing";

  const SimulationParams params;
  SimulatePass pass(*ctx, asset, params);
  SimulationDriver driver(*ctx, pass, HeadAnimation::None, assetHeadRadius(asset));
  hp::test::SimReference reference(pass, params, glm::mat4(1.0f));
  reference.step(driver.nextMotion());
  driver.runFrames(1);
  const std::vector<glm::vec4> gpu = driver.readPositions();
  double deepestGpu = 1e9, deepestCpu = 1e9;
  for (std::size_t i = 0; i < gpu.size(); ++i)
    if (i % n != 0) {
      deepestGpu = std::min(deepestGpu, double(slab(glm::vec3(gpu[i]))));
      deepestCpu = std::min(deepestCpu, double(slab(glm::vec3(reference.positions()[i]))));
    }
  EXPECT_GE(deepestGpu, -1e-4) << "device: deepest particle inside the slab (m)";
  EXPECT_GE(deepestCpu, -1e-4) << "reference: deepest particle inside the slab (m)";
}

TEST_F(VulkanTest, TeleportingTheHeadTenRadiiAwayRecovers) {
  HairAsset asset = thinnedDefaultHead(16);
  SimulatePass pass(*ctx, asset, SimulationParams{});
  const float radius = assetHeadRadius(asset);
  SimulationDriver driver(*ctx, pass, HeadAnimation::Teleport, radius);
  driver.runFrames(70);  // past the jump at t = 1 s
  SimStats away = driver.stats();
  EXPECT_EQ(away.nanCount, 0u);
  EXPECT_LT(away.maxLengthError, 0.01);
  EXPECT_GE(away.minColliderClearance, -1e-4 * radius);
  auto positions = driver.readPositions();
  EXPECT_NEAR(positions[0].x, pass.rest()[0].x + 10.0f * radius, 1e-4) << "roots follow the head";
  driver.runFrames(110);  // and back at t = 2 s, then settle
  SimStats back = driver.stats();
  EXPECT_EQ(back.nanCount, 0u);
  EXPECT_LT(back.maxLengthError, 0.01);
  EXPECT_LT(back.maxSpeed, 1.0);
}

TEST_F(VulkanTest, WithoutForcesDampingDrainsTheKineticEnergy) {
  HairAsset asset = thinnedDefaultHead(16);
  SimulationParams params;
  params.gravity = {0, 0, 0};
  params.stiffness = 0.0;
  params.damping = 0.05;
  SimulatePass pass(*ctx, asset, params);
  SimulationDriver shaker(*ctx, pass, HeadAnimation::Shake, assetHeadRadius(asset));
  shaker.runFrames(24);  // two full shakes: the head is back at rest, the hair still swinging
  SimulationDriver still(*ctx, pass, HeadAnimation::None, assetHeadRadius(asset));
  double previous = still.stats().kineticEnergy;
  ASSERT_GT(previous, 0.0);
  const double start = previous;
  for (int i = 0; i < 6; ++i) {
    still.runFrames(20);
    double now = still.stats().kineticEnergy;
    EXPECT_LT(now, previous) << "after " << 20 * (i + 1) << " still frames";
    previous = now;
  }
  EXPECT_LT(previous, 0.05 * start);
}

TEST_F(VulkanTest, InvalidSimulationInputIsRefusedWithAMessage) {
  HairAsset asset = thinnedDefaultHead(64);
  auto expectError = [&](SimulationParams p, const HairAsset& a, const std::string& needle) {
    try {
      SimulatePass pass(*ctx, a, p);
      ADD_FAILURE() << "expected an error mentioning " << needle;
    } catch (const hp::Error& e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
  };
  SimulationParams p;
  p.dt = 0.0;
  expectError(p, asset, "dt");
  p = {};
  p.dt = std::nan("");
  expectError(p, asset, "dt");
  p = {};
  p.iterations = 0;
  expectError(p, asset, "iterations");
  p.iterations = 1001;
  expectError(p, asset, "iterations");
  p = {};
  p.pearlRadius = -0.1;
  expectError(p, asset, "pearlRadius");
  HairAsset badCollider = asset;
  badCollider.colliders[0].radius = -1.0f;
  expectError({}, badCollider, "collider");
  HairAsset tooMany = asset;
  tooMany.colliders.assign(gpu::SIM_MAX_COLLIDERS + 1, SphereCollider{{0, 0, 0}, 0.1f});
  expectError({}, tooMany, "colliders");
}

// Local shape (SimulationParams::localStiffness, docs/THEORY.md §2.6) on the device against the CPU
// reference, as the test above does without it.
TEST_F(VulkanTest, LocalShapeMatchesTheCpuReferenceOverOneHundredFramesOfNodding) {
  SimulationParams params;
  params.localStiffness = 0.3;
  const Compared c = againstReference(*ctx, params);
  EXPECT_LT(c.maxDifference, 5e-5) << "max |gpu - cpu| in metres";
  EXPECT_GT(c.moved, 1e-3) << "the hair should have moved, or this comparison proves nothing";
}

namespace {
// 16 helical guides growing sideways (+x) from a 4 x 4 grid of roots 5 cm apart on a wall: 25 particles,
// 8 per turn (3 turns) of radius 1 cm and 3 cm pitch; no colliders. Gravity bends them across their axis.
HairAsset helixAsset() {
  HairAsset asset;
  asset.name = "helices";
  asset.guides.particlesPerGuide = 25;
  for (int g = 0; g < 16; ++g) {
    const glm::vec3 root(0.0f, 0.05f * float(g % 4), 0.05f * float(g / 4));
    for (int k = 0; k < 25; ++k) {
      const float a = 6.2831853f * float(k) / 8.0f;
      asset.guides.positions.push_back(root + glm::vec3(0.03f * float(k) / 8.0f, 0.01f * (std::cos(a) - 1.0f),
                                                        0.01f * std::sin(a)));
    }
  }
  return asset;
}

// The helix radius from the strand itself, whatever its axis does: particles half a turn apart lie
// sqrt((2r)^2 + (pitch/2)^2) apart and a whole turn apart one pitch, so r = sqrt(d4^2 - (d8/2)^2) / 2; a
// straightened strand has d4 = d8 / 2 (r = 0). Mean over every guide and position along it.
double meanHelixRadius(const std::vector<glm::vec4>& positions) {
  double sum = 0.0;
  int count = 0;
  for (std::size_t g = 0; g < 16; ++g)
    for (std::size_t k = 0; k + 8 < 25; ++k) {
      const glm::dvec3 a(positions[g * 25 + k]), b(positions[g * 25 + k + 4]), c(positions[g * 25 + k + 8]);
      const double d4 = glm::length(b - a), d8 = glm::length(c - a);
      sum += 0.5 * std::sqrt(std::max(d4 * d4 - 0.25 * d8 * d8, 0.0));
      ++count;
    }
  return sum / count;
}
}  // namespace

// A helical rest shape growing sideways, under gravity through 600 frames of shaking: with local shape on
// (0.5) its helix radius stays within 10% of the rest pose's; without it the helices stretch out. Measured
// on lavapipe: 1.00 cm at rest, 0.935 cm with local shape 0.5 (0.951 at 0.7, 0.907 at 0.9), 0.295 cm
// without. The hair grid is off here: at its recommended values its outflow and friction loosen the coils
// (printed; docs/THEORY.md §2.7).
TEST_F(VulkanTest, LocalShapeKeepsAHelixThroughSixHundredFramesOfShaking) {
  const HairAsset asset = helixAsset();
  std::vector<glm::vec4> rest;
  for (const glm::vec3& p : asset.guides.positions) rest.emplace_back(p, 0.0f);
  const double restRadius = meanHelixRadius(rest);
  auto radiusAfter = [&](double localStiffness, bool grid = false) {
    SimulationParams params = grid ? withHairGrid({}) : SimulationParams{};
    params.localStiffness = localStiffness;
    SimulatePass pass(*ctx, asset, params);
    SimulationDriver driver(*ctx, pass, HeadAnimation::Shake, 0.1f);
    driver.runFrames(600);
    const std::vector<glm::vec4> positions = driver.readPositions();
    for (const glm::vec4& p : positions) EXPECT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
    return meanHelixRadius(positions);
  };
  const double kept = radiusAfter(0.5), without = radiusAfter(0.0);
  std::cout << "helix radius at rest " << restRadius << ", after 600 frames of shaking with local shape " << kept
            << ", without " << without << ", with local shape and the hair grid (volume 0.6, friction 0.1) "
            << radiusAfter(0.5, true) << "\n";
  EXPECT_NEAR(kept / restRadius, 1.0, 0.1);
  EXPECT_LT(without / restRadius, 0.5);
}
