// Opacity shadow maps on the device (docs/THEORY.md §5) against CPU references: the light framing of
// the bounds pass, alpha(z_i) of analytic layered scenes (exact per texel), of a tilted random volume
// and of a small head scene (block sums within stated tolerances), monotonicity in i, T = 1 in front
// of all hair and falling into the volume, and refused settings.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <random>

#include "compute/shadows/bounds_pass.h"
#include "engine/core/error.h"
#include "engine/core/hair/default_head.h"
#include "compute/renderer/frame_recorder.h"
#include "samples/tools/hair_system.h"
#include "samples/tools/opacity_capture.h"
#include "compute/shadows/opacity_pass.h"
#include "engine/vk/submit.h"
#include "engine/vk/transfer.h"
#include "tests/render/opacity_reference.h"
#include "tests/support/vk_fixture.h"

using hp::render::OpacityCapture;
using hp::render::OpacitySettings;
using hp::test::VulkanTest;

namespace {
struct StrandSet {
  std::uint32_t q = 2;
  std::vector<glm::vec4> positions;  // S * q, w = v
  std::uint32_t strands() const { return static_cast<std::uint32_t>(positions.size() / q); }
  void addStraight(const glm::vec3& a, const glm::vec3& b) {
    for (std::uint32_t j = 0; j < q; ++j) {
      const float v = float(j) / float(q - 1);
      positions.emplace_back(glm::mix(a, b, v), v);
    }
  }
};

// Bounds + opacity passes over hand-made strands, recorded as the Renderer records them.
struct ShadowRig {
  std::unique_ptr<hp::compute::StrandBuffers> buffers;
  std::unique_ptr<hp::render::ShadowMaps> maps;
  std::unique_ptr<hp::compute::BoundsPass> bounds;
  std::unique_ptr<hp::render::OpacityPass> opacity;

  ShadowRig(const hp::vk::Context& ctx, const StrandSet& set, const OpacitySettings& settings,
            VkDeviceSize maxChunkBytes = 0,
            hp::render::ShadowMaps::DeepSplats deepSplats = hp::render::ShadowMaps::DeepSplats::Auto) {
    hp::compute::StrandOptions options;
    options.verticesPerStrand = set.q;
    options.guidesOnly = true;
    options.maxChunkBytes = maxChunkBytes;
    buffers = std::make_unique<hp::compute::StrandBuffers>(ctx, set.strands(), 2, hp::InterpolationTopology{}, options);
    for (const auto& chunk : buffers->chunks())
      hp::vk::uploadBytes(ctx, chunk.positions, set.positions.data() + std::size_t(chunk.range.firstStrand) * set.q,
                          VkDeviceSize(chunk.range.strandCount) * set.q * sizeof(glm::vec4), hp::vk::BufferUse::VertexRead);
    maps = std::make_unique<hp::render::ShadowMaps>(ctx, settings, nullptr, 1, deepSplats);
    bounds = std::make_unique<hp::compute::BoundsPass>(ctx, *buffers, maps->lightSpace());
    opacity = std::make_unique<hp::render::OpacityPass>(ctx, *buffers, hp::HeadMesh{}, *maps);
  }

  glm::vec2 strandWidth{0.0005f, 0.35f};  // root width, tip / root: the footprint of every strand

  OpacityCapture run(const hp::vk::Context& ctx, const hp::compute::ShadowLight& light, float marginTexels = 2.0f) {
    hp::compute::BoundsFraming framing;
    framing.resolution = maps->settings().resolution;
    framing.marginTexels = marginTexels;
    hp::vk::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
      // The uploads were transfers of an earlier submission; the bounds read them in compute.
      hp::vk::memoryBarrier(ctx, cmd, hp::vk::BufferUse::TransferDst, hp::vk::BufferUse::ComputeRead);
      const hp::ShadowCaster caster{bounds.get(), opacity.get(), glm::mat4(1.0f), strandWidth};
      hp::recordShadowPasses(ctx, cmd, *maps, std::span(&caster, 1), light, framing);
    }, "shadow rig");
    return hp::render::captureOpacity(ctx, maps->image(), maps->lightSpace(), maps->settings(),
                                      glm::normalize(light.towardLight));
  }
};
}  // namespace

namespace {
OpacitySettings smallSettings(std::uint32_t resolution, float strandOpacity) {
  OpacitySettings s;
  s.deep = false;  // the global slices (deep maps: DeepOpacityMapsStartAtEachTexelsFirstHair)
  s.resolution = resolution;
  s.footprint = false;  // the constant-per-crossing mode: alpha is exactly crossings x strandOpacity
  s.strandOpacity = strandOpacity;
  return s;
}

// Three layers of 40 parallel strands along x, facing a light toward +z: light depths 0, 0.3 and 1.
StrandSet layeredScene() {
  StrandSet set;
  set.q = 4;
  for (float z : {0.0f, -0.3f, -1.0f})
    for (int j = 0; j < 40; ++j) {
      const float y = -0.5f + float(j) / 39.0f;
      set.addStraight({-0.5f, y, z}, {0.5f, y, z});
    }
  return set;
}

// The layers of layeredScene seen from a spot at (0, 0, 2) looking down -z: layer k at spot depth
// d_k = 2, 2.3, 3 is scaled by d_k / 2, so all three project onto the same lines of the map
// (x/d, y/d in [-0.25, 0.25]).
constexpr float kSpotZ = 2.0f;
StrandSet layeredSpotScene() {
  StrandSet set;
  set.q = 4;
  for (float z : {0.0f, -0.3f, -1.0f}) {
    const float scale = (kSpotZ - z) / kSpotZ;
    for (int j = 0; j < 40; ++j) {
      const float y = (-0.5f + float(j) / 39.0f) * scale;
      set.addStraight({-0.5f * scale, y, z}, {0.5f * scale, y, z});
    }
  }
  return set;
}

// 300 wavy strands in a unit ball, random directions.
StrandSet tiltedVolume() {
  StrandSet set;
  set.q = 12;
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(-1.0f, 1.0f);
  for (int s = 0; s < 300; ++s) {
    glm::vec3 root(u(rng), u(rng), u(rng)), dir = glm::normalize(glm::vec3(u(rng), u(rng), u(rng)));
    root *= 0.6f;
    for (std::uint32_t j = 0; j < set.q; ++j) {
      const float t = float(j) / float(set.q - 1);
      set.positions.emplace_back(root + dir * (0.5f * t) + 0.05f * glm::vec3(std::sin(9.0f * t), std::cos(7.0f * t), 0.0f), t);
    }
  }
  return set;
}

hp::test::OpacityGrid referenceOf(const StrandSet& set, const OpacityCapture& c) {
  hp::test::OpacityGrid grid{c.resolution, std::vector<double>(c.alpha.size(), 0.0)};
  std::vector<glm::dvec3> a, b;
  for (std::uint32_t s = 0; s < set.strands(); ++s)
    for (std::uint32_t j = 0; j + 1 < set.q; ++j) {
      a.emplace_back(set.positions[s * set.q + j]);
      b.emplace_back(set.positions[s * set.q + j + 1]);
    }
  hp::test::rasterizeSegments(grid, c.light, a, b, c.settings.strandOpacity);
  return grid;
}

// Device vs CPU reference on one slice: the fraction of the reference's non-empty texels that differ
// (relative 1e-3), the texel-wise L1 difference relative to the slice's total, the relative difference
// of the slice totals, and the relative L1 difference of block x block sums (where the line and
// triangle rules pick a neighbouring texel, sums still agree).
struct SliceError {
  double texelMismatch = 0.0;
  double texelL1 = 0.0;
  double total = 0.0;
  double blockL1 = 0.0;
};
SliceError sliceError(const OpacityCapture& c, const hp::test::OpacityGrid& ref, std::uint32_t slice,
                      std::uint32_t block) {
  std::size_t mismatched = 0, nonEmpty = 0;
  double dev = 0.0, cpu = 0.0, blockDiff = 0.0, texelDiff = 0.0;
  for (std::uint32_t by = 0; by < c.resolution; by += block)
    for (std::uint32_t bx = 0; bx < c.resolution; bx += block) {
      double devBlock = 0.0, cpuBlock = 0.0;
      for (std::uint32_t y = by; y < by + block; ++y)
        for (std::uint32_t x = bx; x < bx + block; ++x) {
          const double d = c.at(slice, x, y), r = ref.at(slice, x, y);
          nonEmpty += r > 0.0;
          mismatched += std::abs(d - r) > 1e-3 * (1.0 + r);
          texelDiff += std::abs(d - r);
          devBlock += d;
          cpuBlock += r;
        }
      dev += devBlock;
      cpu += cpuBlock;
      blockDiff += std::abs(devBlock - cpuBlock);
    }
  SliceError e;
  e.texelMismatch = nonEmpty ? double(mismatched) / double(nonEmpty) : double(mismatched);
  e.texelL1 = cpu > 0.0 ? texelDiff / cpu : texelDiff;
  e.total = cpu > 0.0 ? std::abs(dev - cpu) / cpu : dev;
  e.blockL1 = cpu > 0.0 ? blockDiff / cpu : blockDiff;
  return e;
}
}  // namespace

// The opacity tests run on both ways into the maps (OpacitySettings::raster): compute splats and graphics lines.
class OpacityMapTest : public VulkanTest, public ::testing::WithParamInterface<hp::render::OpacityRaster> {
 protected:
  OpacitySettings onRaster(OpacitySettings s) const {
    s.raster = GetParam();
    return s;
  }
};
INSTANTIATE_TEST_SUITE_P(Raster, OpacityMapTest,
                         ::testing::Values(hp::render::OpacityRaster::Compute, hp::render::OpacityRaster::Graphics),
                         [](const auto& info) { return std::string(hp::render::opacityRasterName(info.param)); });

TEST(OpacitySettings, RefusesBadValuesNamingTheField) {
  auto refuses = [](OpacitySettings s, const std::string& field) {
    try {
      hp::render::validate(s);
    } catch (const hp::Error& e) {
      EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
      return;
    }
    ADD_FAILURE() << "accepted a bad " << field;
  };
  OpacitySettings s;
  EXPECT_NO_THROW(hp::render::validate(s));
  for (std::uint32_t r : {0u, 8u, 5000u, 0xffffffffu}) {
    s = {};
    s.resolution = r;
    refuses(s, "resolution");
  }
  for (float v : {NAN, -1.0f, 0.0f, INFINITY, 1e9f}) {
    s = {};
    s.strandOpacity = v;
    refuses(s, "strandOpacity");
  }
  for (float v : {NAN, -0.5f, INFINITY}) {
    s = {};
    s.k = v;
    refuses(s, "k");
    s = {};
    s.headOpacity = v;
    refuses(s, "headOpacity");
  }
  for (float v : {NAN, -1.0f, 17.0f}) {
    s = {};
    s.biasSlices = v;
    refuses(s, "biasSlices");
    s = {};
    s.deepBiasSlices = v;
    refuses(s, "deepBiasSlices");
  }
  s = {};
  s.format = VK_FORMAT_R8G8B8A8_UNORM;
  refuses(s, "format");
}

TEST_F(VulkanTest, HairSystemRefusesBadOpacitySettings) {
  hp::DensityOptions density;
  density.totalStrands = 200;
  const hp::HairAsset asset = hp::buildDefaultHeadAsset(hp::defaultHeadGrowth(), density);
  hp::HairSystemSettings settings;
  settings.opacity.k = -1.0f;
  try {
    hp::HairSystem hair(*ctx, asset, settings);
    ADD_FAILURE() << "accepted k = -1";
  } catch (const hp::Error& e) {
    EXPECT_NE(std::string(e.what()).find("k must be"), std::string::npos) << e.what();
  }
}

namespace {
// Which of the 64 map rows hold a strand of the 40 parallel strands at x = 0 (y from -0.5 to 0.5), and
// which rows are ambiguous because a strand lies within 0.05 texel of a row boundary.
std::pair<std::vector<int>, std::vector<bool>> strandRows(const hp::gpu::LightSpace& light) {
  std::vector<int> count(64, 0);
  std::vector<bool> ambiguous(64, false);
  for (int j = 0; j < 40; ++j) {
    const double v = hp::test::texelAndSlice(light, 64, {0.0, -0.5 + j / 39.0, 0.0}).y;
    const int row = int(std::floor(v));
    count[row] += 1;
    const double f = v - row;
    if (f < 0.05) ambiguous[std::max(row - 1, 0)] = ambiguous[row] = true;
    if (f > 0.95) ambiguous[std::min(row + 1, 63)] = ambiguous[row] = true;
  }
  return {count, ambiguous};
}
}  // namespace

TEST_P(OpacityMapTest, OpacityOfParallelLayersIsExactPerTexel) {
  const StrandSet set = layeredScene();
  const float o = 0.25f;
  ShadowRig rig(*ctx, set, onRaster(smallSettings(64, o)));
  const OpacityCapture c = rig.run(*ctx, glm::vec3(0.0f, 0.0f, 1.0f));
  // Framing: x, y = world x, y padded by 2 texels of the extent; depth d = -z in [0, 1].
  const float pad = 1.0f * 2.0f / 64.0f;
  EXPECT_NEAR(c.light.extent.x, -0.5f - pad, 1e-6f);
  EXPECT_NEAR(c.light.extent.w, 0.5f + pad, 1e-6f);
  EXPECT_NEAR(c.light.depthRange.x, 0.0f, 1e-6f);
  EXPECT_NEAR(c.light.depthRange.y, 1.0f, 1e-6f);
  EXPECT_NEAR(c.light.depthRange.z, 1.0f / 16.0f, 1e-7f);
  for (std::uint32_t i = 1; i <= 16; ++i) EXPECT_NEAR(c.sliceDepth(i), i / 16.0f, 1e-6f);

  // Rows holding a strand (skip rows whose strand lies within 0.05 texel of a row boundary).
  const auto [count, ambiguous] = strandRows(c.light);
  // Layer at s = 0 reaches slices 1..16, at s = 4.8 slices 5..16, at s = 16 (z_far) slice 16.
  std::size_t checked = 0, wrong = 0;
  for (std::uint32_t y = 0; y < 64; ++y) {
    if (ambiguous[y]) continue;
    for (std::uint32_t x = 5; x < 59; ++x)
      for (std::uint32_t i = 1; i <= 16; ++i) {
        const float expected = o * count[y] * (1.0f + (i >= 5 ? 1.0f : 0.0f) + (i == 16 ? 1.0f : 0.0f));
        ++checked;
        if (std::abs(c.at(i - 1, x, y) - expected) > 1e-5f) ++wrong;
      }
  }
  EXPECT_GT(checked, 16u * 54u * 40u);
  EXPECT_EQ(wrong, 0u);
  // Eq. 10 between the slices, and T = 1 in front of everything.
  const std::uint32_t x = 32;
  std::uint32_t y = 0;
  while (count[y] != 1 || ambiguous[y]) ++y;
  EXPECT_DOUBLE_EQ(hp::test::lookupAlpha(c, x, y, 0.0), 0.0);
  EXPECT_NEAR(hp::test::lookupAlpha(c, x, y, 0.5), 0.5 * o, 1e-6);
  EXPECT_NEAR(hp::test::lookupAlpha(c, x, y, 4.5), 1.5 * o, 1e-6);
  EXPECT_NEAR(hp::test::lookupAlpha(c, x, y, 16.0), 3.0 * o, 1e-6);
}

// A spot light's perspective framing: x/d, y/d box padded by 2 texels, depths [2, 3] along its axis,
// and alpha(z_i) exact per texel as for the directional layers (the layers project onto one grid).
TEST_P(OpacityMapTest, SpotOpacityOfParallelLayersIsExactPerTexel) {
  const StrandSet set = layeredSpotScene();
  const float o = 0.25f;
  ShadowRig rig(*ctx, set, onRaster(smallSettings(64, o)));
  const auto spot = hp::compute::ShadowLight::makeSpot({0.0f, 0.0f, kSpotZ}, {0.0f, 0.0f, 1.0f}, glm::radians(30.0f));
  const OpacityCapture c = rig.run(*ctx, spot);
  const float pad = 0.5f * 2.0f / 64.0f;
  EXPECT_NEAR(c.light.extent.x, -0.25f - pad, 1e-6f);
  EXPECT_NEAR(c.light.extent.y, -0.25f - pad, 1e-6f);
  EXPECT_NEAR(c.light.extent.z, 0.25f + pad, 1e-6f);
  EXPECT_NEAR(c.light.extent.w, 0.25f + pad, 1e-6f);
  EXPECT_NEAR(c.light.depthRange.x, 2.0f, 1e-6f);
  EXPECT_NEAR(c.light.depthRange.y, 3.0f, 1e-6f);
  for (std::uint32_t i = 1; i <= 16; ++i) EXPECT_NEAR(c.sliceDepth(i), 2.0f + i / 16.0f, 1e-6f);
  // The perspective projection against the CPU: texel and slice of points at known spot coordinates.
  for (const glm::dvec3 p : {glm::dvec3(0, 0, 0), glm::dvec3(0.2, -0.1, -0.5), glm::dvec3(-0.6, 0.3, -1.0)}) {
    const double d = kSpotZ - p.z;
    const double half = 0.25 + pad;
    const glm::dvec3 got = hp::test::texelAndSlice(c.light, 64, p);
    EXPECT_NEAR(got.x, (p.x / d + half) / (2 * half) * 64, 1e-4);
    EXPECT_NEAR(got.y, (half - p.y / d) / (2 * half) * 64, 1e-4);
    EXPECT_NEAR(got.z, 16.0 * (d - 2.0), 1e-4);
  }

  const auto [count, ambiguous] = strandRows(c.light);
  std::size_t checked = 0, wrong = 0, decreasing = 0, nonZeroFront = 0;
  for (std::uint32_t y = 0; y < 64; ++y)
    for (std::uint32_t x = 0; x < 64; ++x) {
      for (std::uint32_t i = 1; i < 16; ++i) decreasing += c.at(i, x, y) < c.at(i - 1, x, y);
      nonZeroFront += hp::test::lookupAlpha(c, x, y, 0.0) != 0.0;
      if (ambiguous[y] || x < 5 || x >= 59) continue;
      for (std::uint32_t i = 1; i <= 16; ++i) {
        const float expected = o * count[y] * (1.0f + (i >= 5 ? 1.0f : 0.0f) + (i == 16 ? 1.0f : 0.0f));
        ++checked;
        if (std::abs(c.at(i - 1, x, y) - expected) > 1e-5f) ++wrong;
      }
    }
  EXPECT_GT(checked, 16u * 54u * 40u);
  EXPECT_EQ(wrong, 0u);
  EXPECT_EQ(decreasing, 0u);
  EXPECT_EQ(nonZeroFront, 0u);
}

// The cone caps the framing: a 10-degree spot maps only +-tan(10 deg) of the same hair, and a
// tilted volume's framing matches the CPU reduction of (x/d, y/d, d).
TEST_P(OpacityMapTest, SpotFramingIsCappedByTheConeAndMatchesTheCpuReduction) {
  {
    ShadowRig rig(*ctx, layeredSpotScene(), onRaster(smallSettings(64, 0.25f)));
    const float cone = glm::radians(10.0f), t = std::tan(cone), pad = 2.0f * t * 2.0f / 64.0f;
    const OpacityCapture c = rig.run(*ctx, hp::compute::ShadowLight::makeSpot({0, 0, kSpotZ}, {0, 0, 1}, cone));
    EXPECT_NEAR(c.light.extent.x, -t - pad, 1e-6f);
    EXPECT_NEAR(c.light.extent.w, t + pad, 1e-6f);
  }
  const StrandSet set = tiltedVolume();
  const glm::vec3 position(1.2f, 2.0f, 1.5f), toward = glm::normalize(position);  // aimed at the origin
  ShadowRig rig(*ctx, set, onRaster(smallSettings(128, 0.1f)), VkDeviceSize(100) * set.q * sizeof(glm::vec4));
  const OpacityCapture c = rig.run(*ctx, hp::compute::ShadowLight::makeSpot(position, toward, glm::radians(40.0f)));
  const hp::test::LightBox box = hp::test::spotBounds(set.positions, position, toward);
  ASSERT_LT(std::max({-box.lo.x, -box.lo.y, box.hi.x, box.hi.y}), std::tan(glm::radians(40.0)));  // inside the cone
  EXPECT_NEAR(c.light.depthRange.x, box.lo.z, 1e-5);
  EXPECT_NEAR(c.light.depthRange.y, box.hi.z, 1e-5);
  const double padX = (box.hi.x - box.lo.x) * 2.0 / 128.0, padY = (box.hi.y - box.lo.y) * 2.0 / 128.0;
  EXPECT_NEAR(c.light.extent.x, box.lo.x - padX, 1e-5);
  EXPECT_NEAR(c.light.extent.y, box.lo.y - padY, 1e-5);
  EXPECT_NEAR(c.light.extent.z, box.hi.x + padX, 1e-5);
  EXPECT_NEAR(c.light.extent.w, box.hi.y + padY, 1e-5);
  // Every vertex lands inside the map, at a slice coordinate in [0, 16]; alpha never falls with i.
  for (const glm::vec4& p : set.positions) {
    const glm::dvec3 ts = hp::test::texelAndSlice(c.light, 128, glm::dvec3(p));
    EXPECT_TRUE(ts.x > 0 && ts.x < 128 && ts.y > 0 && ts.y < 128 && ts.z > -1e-4 && ts.z < 16 + 1e-4);
  }
  std::size_t decreasing = 0;
  for (std::uint32_t y = 0; y < 128; ++y)
    for (std::uint32_t x = 0; x < 128; ++x)
      for (std::uint32_t i = 1; i < 16; ++i) decreasing += c.at(i, x, y) < c.at(i - 1, x, y);
  EXPECT_EQ(decreasing, 0u);
}

TEST_P(OpacityMapTest, OpacityOfATiltedVolumeMatchesTheCpuRasterizer) {
  const StrandSet set = tiltedVolume();
  const glm::vec3 light = glm::normalize(glm::vec3(0.3f, 0.8f, 0.5f));
  // 100 strands per chunk: the reduction and the draws span 3 chunks.
  ShadowRig rig(*ctx, set, onRaster(smallSettings(128, 0.1f)), VkDeviceSize(100) * set.q * sizeof(glm::vec4));
  ASSERT_EQ(rig.buffers->chunks().size(), 3u);
  const OpacityCapture c = rig.run(*ctx, light);

  // Framing against the CPU reduction.
  const hp::test::LightBox box = hp::test::lightBounds(set.positions, light);
  EXPECT_NEAR(c.light.depthRange.x, box.lo.z, 1e-5);
  EXPECT_NEAR(c.light.depthRange.y, box.hi.z, 1e-5);
  const double padX = (box.hi.x - box.lo.x) * 2.0 / 128.0, padY = (box.hi.y - box.lo.y) * 2.0 / 128.0;
  EXPECT_NEAR(c.light.extent.x, box.lo.x - padX, 1e-5);
  EXPECT_NEAR(c.light.extent.y, box.lo.y - padY, 1e-5);
  EXPECT_NEAR(c.light.extent.z, box.hi.x + padX, 1e-5);
  EXPECT_NEAR(c.light.extent.w, box.hi.y + padY, 1e-5);

  // alpha(z_i) is non-decreasing in i for every texel, T = 1 in front of all hair, T falls inside.
  std::size_t decreasing = 0, nonZeroFront = 0, hairTexels = 0, notFalling = 0;
  for (std::uint32_t y = 0; y < 128; ++y)
    for (std::uint32_t x = 0; x < 128; ++x) {
      for (std::uint32_t i = 1; i < 16; ++i) decreasing += c.at(i, x, y) < c.at(i - 1, x, y);
      nonZeroFront += hp::test::lookupAlpha(c, x, y, 0.0) != 0.0;
      if (c.at(15, x, y) == 0.0f) continue;
      ++hairTexels;
      double previous = 0.0;
      for (double s = 0.0; s <= 16.0; s += 0.25) {
        const double alpha = hp::test::lookupAlpha(c, x, y, s);
        notFalling += alpha < previous;  // T = exp(-k alpha) must not rise with depth
        previous = alpha;
      }
      notFalling += std::exp(-c.settings.k * previous) >= 1.0;
    }
  EXPECT_EQ(decreasing, 0u);
  EXPECT_EQ(nonZeroFront, 0u);
  EXPECT_GT(hairTexels, 2000u);
  EXPECT_EQ(notFalling, 0u);

  // Against the CPU strict-line rasterizer. Tolerance: at most 1.5% of the texels differ (sub-texel
  // ties of the device's fixed-point rasterizer, depths at a slice boundary), slice totals within
  // 0.5%, 8x8 block sums within 3% (relative L1). Measured: <= 0.9% of texels, totals ~1e-7.
  const hp::test::OpacityGrid ref = referenceOf(set, c);
  for (std::uint32_t slice = 0; slice < 16; ++slice) {
    const SliceError e = sliceError(c, ref, slice, 8);
    EXPECT_LE(e.texelMismatch, 0.015) << "slice " << slice + 1;
    EXPECT_LT(e.total, 0.005) << "slice " << slice + 1;
    EXPECT_LT(e.blockL1, 0.03) << "slice " << slice + 1;
  }
}

TEST_P(OpacityMapTest, OpacityOfASmallHeadSceneMatchesTheCpuReference) {
  hp::DensityOptions density;
  density.totalStrands = 3000;
  const hp::HairAsset asset = hp::buildDefaultHeadAsset(hp::defaultHeadGrowth(), density);
  hp::HairSystemSettings settings;
  settings.opacity.resolution = 128;
  settings.opacity.footprint = false;
  settings.opacity.strandOpacity = 0.1f;
  settings.opacity.raster = GetParam();
  settings.opacity.deep = false;  // the CPU reference slices the whole depth
  hp::HairSystem hair(*ctx, asset, settings);
  hp::DrawView view;
  view.lights[0].direction = glm::normalize(glm::vec3(0.4f, 0.7f, -0.6f));
  hp::vk::submitAndWait(*ctx, [&](VkCommandBuffer cmd) {
    hair.recordUpdate(cmd, hp::HeadMotion{});
    hair.recordPrepareDraw(cmd, view);
  }, "head scene frame");
  const OpacityCapture c = hp::render::captureOpacity(*ctx, hair.shadows().image(), hair.shadows().lightSpace(),
                                                      settings.opacity, view.lights[0].direction);
  const hp::compute::StrandData strands = hp::compute::readRenderStrands(*ctx, hair.strands(), hp::vk::BufferUse::VertexRead);

  const hp::test::LightBox box = hp::test::lightBounds(strands.positions, view.lights[0].direction);
  EXPECT_NEAR(c.light.depthRange.x, box.lo.z, 1e-5);
  EXPECT_NEAR(c.light.depthRange.y, box.hi.z, 1e-5);

  StrandSet set;
  set.q = hair.strands().layout().verticesPerStrand;
  set.positions = strands.positions;
  hp::test::OpacityGrid ref = referenceOf(set, c);
  std::vector<glm::dvec3> corners;
  for (std::uint32_t i : asset.head.indices) corners.emplace_back(asset.head.positions[i]);
  hp::test::rasterizeTriangles(ref, c.light, corners, settings.opacity.headOpacity);
  // Tolerance: the texel-wise L1 difference within 1% of the slice's total (where the device's
  // fixed-point line rule and the strict-line rule pick a neighbouring texel, each such deposit counts
  // twice), slice totals within 0.5%, 16x16 block sums within 3% (relative L1). Not the fraction of
  // differing texels as in the sparse test above: here a texel sums many strands and differs if any one of
  // them does, so that fraction grows with the hair's density and depth (1% in the first slice, 6% in the
  // last) while the share of deposits that moved stays the same. Measured: L1 <= 0.34% (gcc), <= 0.42%
  // (clang sanitizer build); texels differing up to 5.9% / 6.2%; totals within 0.01%.
  double worstL1 = 0.0;
  for (std::uint32_t slice = 0; slice < 16; ++slice) {
    const SliceError e = sliceError(c, ref, slice, 16);
    worstL1 = std::max(worstL1, e.texelL1);
    EXPECT_LT(e.texelL1, 0.01) << "slice " << slice + 1;
    EXPECT_LT(e.total, 0.005) << "slice " << slice + 1;
    EXPECT_LT(e.blockL1, 0.03) << "slice " << slice + 1;
  }
  std::printf("head scene: worst slice's texel L1 difference %.4f of its total\n", worstL1);
}

namespace {
// K layers of parallel strands along x, spacing `spacing` in y (not a multiple of the texel), at the
// given depths below z = 0; for a spot at (0, 0, kSpotZ) each layer is scaled by its spot depth / kSpotZ
// (its strands stay `width` wide, so its covered fraction is width / (spacing x scale)).
StrandSet footprintLayers(const std::vector<float>& depths, float spacing, bool spot) {
  StrandSet set;
  set.q = 2;
  for (float z : depths) {
    const float scale = spot ? (kSpotZ - z) / kSpotZ : 1.0f;
    for (float y = -0.5f; y <= 0.5f; y += spacing)
      set.addStraight({-0.5f * scale, y * scale, z}, {0.5f * scale, y * scale, z});
  }
  return set;
}

// Mean transmittance exp(-alpha) behind all layers (slice 16) over the interior texels.
double meanTransmittanceBehind(const OpacityCapture& c) {
  double sum = 0.0;
  std::size_t n = 0;
  for (std::uint32_t y = c.resolution / 8; y < c.resolution * 7 / 8; ++y)
    for (std::uint32_t x = c.resolution / 8; x < c.resolution * 7 / 8; ++x, ++n) sum += std::exp(-c.at(15, x, y));
  return sum / double(n);
}

OpacitySettings footprintSettings(std::uint32_t resolution) {
  OpacitySettings s;
  s.deep = false;
  s.resolution = resolution;
  return s;
}
}  // namespace

// Footprint opacity (the default): layers of strands of known width and spacing transmit what
// Beer-Lambert predicts for their covered fraction, T = exp(-sum_k width / spacing_k), at two map
// resolutions and for a spot (whose texels grow with depth). Spacing 1/173: ~3 strands per texel.
TEST_P(OpacityMapTest, FootprintOpacityOfStrandLayersFollowsBeerLambert) {
  const float spacing = 1.0f / 173.0f, width = 0.15f * spacing;
  const std::vector<float> depths = {0.0f, -0.25f, -0.5f, -1.0f};
  const double expected = std::exp(-double(depths.size()) * width / spacing);
  for (std::uint32_t res : {64u, 128u}) {
    ShadowRig rig(*ctx, footprintLayers(depths, spacing, false), onRaster(footprintSettings(res)));
    rig.strandWidth = {width, 1.0f};
    const double t = meanTransmittanceBehind(rig.run(*ctx, glm::vec3(0.0f, 0.0f, 1.0f)));
    std::cout << "directional, " << res << "^2: T = " << t << ", Beer-Lambert " << expected << "\n";
    EXPECT_NEAR(t / expected, 1.0, 0.05) << res;
  }
  double spotAlpha = 0.0;
  for (float z : depths) spotAlpha += width / (spacing * (kSpotZ - z) / kSpotZ);
  const auto spot = hp::compute::ShadowLight::makeSpot({0.0f, 0.0f, kSpotZ}, {0.0f, 0.0f, 1.0f}, glm::radians(30.0f));
  ShadowRig rig(*ctx, footprintLayers(depths, spacing, true), onRaster(footprintSettings(128)));
  rig.strandWidth = {width, 1.0f};
  const double t = meanTransmittanceBehind(rig.run(*ctx, spot));
  std::cout << "spot, 128^2: T = " << t << ", Beer-Lambert " << std::exp(-spotAlpha) << "\n";
  EXPECT_NEAR(t / std::exp(-spotAlpha), 1.0, 0.05);
}

namespace {
// The default head's maps after one frame with the given settings and light.
OpacityCapture headSceneMaps(const hp::vk::Context& ctx, const hp::HairAsset& asset, const OpacitySettings& opacity,
                             const hp::LightSpec& light) {
  hp::HairSystemSettings settings;
  settings.opacity = opacity;
  hp::HairSystem hair(ctx, asset, settings);
  hp::DrawView view;
  view.lights = {light};
  hp::vk::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
    hair.recordUpdate(cmd, hp::HeadMotion{});
    hair.recordPrepareDraw(cmd, view);
  }, "opacity raster frame");
  return hp::render::captureOpacity(ctx, hair.shadows().image(), hair.shadows().lightSpace(), opacity,
                                    glm::normalize(light.direction));
}
}  // namespace

// The compute splat + resolve against the graphics lines on the default head (footprint opacity, 256^2),
// for a directional light, a spot, and with the head drawn into the slices over the resolved maps
// (headOpacity > 0: the graphics draw after the resolve). The same rule and opacities, but lavapipe's
// lines snap to its subpixel grid where the splat (like the CPU reference above) does not, so a deposit
// near a texel edge can land one texel over: the bounds of the CPU-reference test, per slice (texel-wise
// L1 < 1% of the slice's total, totals < 0.5%, 16x16 block sums < 3%). Measured: L1 <= 0.3%.
TEST_F(VulkanTest, ComputeAndGraphicsOpacityMapsAgreeOnTheDefaultHead) {
  hp::DensityOptions density;
  density.totalStrands = 3000;
  const hp::HairAsset asset = hp::buildDefaultHeadAsset(hp::defaultHeadGrowth(), density);
  hp::LightSpec sun;
  sun.direction = glm::normalize(glm::vec3(0.4f, 0.7f, -0.6f));
  const hp::LightSpec spot = hp::LightSpec::makeSpot({0.3f, 0.5f, 0.6f}, {0.0f, 0.1f, 0.0f}, 35.0f);
  struct Case {
    const char* name;
    hp::LightSpec light;
    float headOpacity;
  };
  for (const Case& k : {Case{"sun", sun, 0.0f}, Case{"spot", spot, 0.0f}, Case{"sun, head in slices", sun, 5.0f}}) {
    OpacitySettings s;
    s.deep = false;  // the graphics path has global slices only
    s.resolution = 256;
    s.headOpacity = k.headOpacity;
    s.raster = hp::render::OpacityRaster::Compute;
    const OpacityCapture compute = headSceneMaps(*ctx, asset, s, k.light);
    s.raster = hp::render::OpacityRaster::Graphics;
    const OpacityCapture graphics = headSceneMaps(*ctx, asset, s, k.light);
    ASSERT_EQ(compute.alpha.size(), graphics.alpha.size());
    const hp::test::OpacityGrid reference{graphics.resolution,
                                          std::vector<double>(graphics.alpha.begin(), graphics.alpha.end())};
    double worstL1 = 0.0, total = 0.0;
    for (std::uint32_t slice = 0; slice < 16; ++slice) {
      const SliceError e = sliceError(compute, reference, slice, 16);
      worstL1 = std::max(worstL1, e.texelL1);
      EXPECT_LT(e.texelL1, 0.01) << k.name << ", slice " << slice + 1;
      EXPECT_LT(e.total, 0.005) << k.name << ", slice " << slice + 1;
      EXPECT_LT(e.blockL1, 0.03) << k.name << ", slice " << slice + 1;
    }
    for (float a : graphics.alpha) total += a;
    std::printf("%s: worst slice's texel L1 difference %.4f of its total (all slices: %.0f)\n", k.name, worstL1, total);
    EXPECT_GT(total, 1000.0) << k.name;
  }
}

// OpacitySettings::shadowStrands: past the budget the maps draw the first shadowStrands strands (an even
// sample), widened by strands / shadowStrands, so the hair's total opacity stays; the same number of strands at
// their own width leave about half of it out. A budget at or above the strand count draws every strand: the
// same maps bit for bit (fixed-point sums do not depend on order).
TEST_F(VulkanTest, AShadowStrandBudgetKeepsTheMapsTotalOpacity) {
  hp::DensityOptions density;
  density.totalStrands = 4000;
  const hp::HairAsset asset = hp::buildDefaultHeadAsset(hp::defaultHeadGrowth(), density);
  density.totalStrands = 2000;
  const hp::HairAsset halfAsset = hp::buildDefaultHeadAsset(hp::defaultHeadGrowth(), density);
  hp::LightSpec sun;
  sun.direction = glm::normalize(glm::vec3(0.4f, 0.7f, -0.6f));
  OpacitySettings s;
  s.resolution = 256;
  const auto total = [](const OpacityCapture& c) {  // the last slice: every texel's whole opacity
    double sum = 0.0;
    for (std::uint32_t y = 0; y < c.resolution; ++y)
      for (std::uint32_t x = 0; x < c.resolution; ++x) sum += c.at(15, x, y);
    return sum;
  };
  const OpacityCapture all = headSceneMaps(*ctx, asset, s, sun);
  const OpacityCapture thin = headSceneMaps(*ctx, halfAsset, s, sun);
  s.shadowStrands = 2000;
  const OpacityCapture sample = headSceneMaps(*ctx, asset, s, sun);
  s.shadowStrands = 4000;
  const OpacityCapture within = headSceneMaps(*ctx, asset, s, sun);
  std::printf("total opacity: all %.0f, budget of half %.0f, half the strands at their width %.0f\n", total(all),
              total(sample), total(thin));
  EXPECT_NEAR(total(sample) / total(all), 1.0, 0.05);
  EXPECT_LT(total(thin) / total(all), 0.6);
  EXPECT_NE(sample.alpha, all.alpha);  // the budget took effect
  EXPECT_EQ(within.alpha, all.alpha);
  EXPECT_EQ(within.firstHair, all.firstHair);
}

// 700 coincident strands of opacity 100 pile 70,000 into each texel's first bin: past the 32-bit fixed
// point (65,536), where a plain sum would wrap to ~4,464. The bins saturate instead: every slice at and
// behind the pile reads OPACITY_SATURATED_ALPHA (T = 0), in global and in both kinds of deep bins; the
// graphics path's sum is the true 70,000.
TEST_F(VulkanTest, ComputeOpacityBinsSaturateInsteadOfWrappingAround) {
  StrandSet set;
  set.q = 2;
  for (int i = 0; i < 700; ++i) set.addStraight({-0.5f, 0.013f, 0.0f}, {0.5f, 0.013f, 0.0f});
  set.addStraight({-0.5f, 0.4f, -1.0f}, {0.5f, 0.4f, -1.0f});  // a second depth: the framing spans [0, 1]
  OpacitySettings s;
  s.resolution = 64;
  s.footprint = false;
  s.strandOpacity = 100.0f;
  using hp::compute::OpacityBins;
  using DeepSplats = hp::render::ShadowMaps::DeepSplats;
  struct Case {
    hp::render::OpacityRaster raster;
    bool deep;
    DeepSplats splats;
    OpacityBins bins;  // what the compute path must have taken
  };
  for (const Case& k : {Case{hp::render::OpacityRaster::Compute, false, DeepSplats::Auto, OpacityBins::Global},
                        Case{hp::render::OpacityRaster::Compute, true, DeepSplats::Auto, OpacityBins::DeepFine},
                        Case{hp::render::OpacityRaster::Compute, true, DeepSplats::Two, OpacityBins::DeepTwoSplats},
                        Case{hp::render::OpacityRaster::Graphics, false, DeepSplats::Auto, OpacityBins::Global}}) {
    const hp::render::OpacityRaster raster = k.raster;
    s.raster = raster;
    s.deep = k.deep;
    ShadowRig rig(*ctx, set, s, 0, k.splats);
    if (raster == hp::render::OpacityRaster::Compute) {
      EXPECT_EQ(rig.maps->resolvePass()->layout(), k.bins);
    }
    const OpacityCapture c = rig.run(*ctx, glm::vec3(0.0f, 0.0f, 1.0f));
    std::size_t pile = 0;
    for (std::uint32_t y = 0; y < 64; ++y)
      for (std::uint32_t x = 8; x < 56; ++x) {
        if (c.at(0, x, y) < 1000.0f) continue;
        ++pile;
        for (std::uint32_t i = 0; i < 16; ++i) {
          if (raster == hp::render::OpacityRaster::Compute)
            EXPECT_EQ(c.at(i, x, y), hp::gpu::OPACITY_SATURATED_ALPHA) << x << "," << y << " slice " << i + 1;
          else
            EXPECT_NEAR(c.at(i, x, y), 70000.0f, 1.0f) << x << "," << y << " slice " << i + 1;
        }
      }
    EXPECT_GE(pile, 48u) << hp::render::opacityRasterName(raster) << " deep " << k.deep;
  }
}

// A saturated bin that a deep slice takes only a share of saturates the slice: one fibre at s = 0.125 is
// each texel's first hair (fine coordinate 0.5), 700 coincident strands of opacity 100 pile up behind it at
// s = 0.3 (fine bin 1, deep coordinate 0.7): slice 1 holds half that bin in one splat, all of it in two, and
// every slice reads OPACITY_SATURATED_ALPHA in both forms.
TEST_F(VulkanTest, ADeepSliceWithAShareOfASaturatedBinSaturates) {
  StrandSet set;
  set.q = 2;
  set.addStraight({-0.9f, -0.5f, 0.0f}, {-0.9f, 0.5f, 0.0f});  // light depth 0 and
  set.addStraight({-0.5f, 0.4f, -1.0f}, {0.5f, 0.4f, -1.0f});   // 1: the framing spans [0, 1]
  set.addStraight({-0.5f, 0.013f, -0.125f / 16.0f}, {0.5f, 0.013f, -0.125f / 16.0f});
  for (int i = 0; i < 700; ++i) set.addStraight({-0.5f, 0.013f, -0.3f / 16.0f}, {0.5f, 0.013f, -0.3f / 16.0f});
  OpacitySettings s;
  s.resolution = 64;
  s.footprint = false;
  s.strandOpacity = 100.0f;
  s.deep = true;
  s.raster = hp::render::OpacityRaster::Compute;
  using DeepSplats = hp::render::ShadowMaps::DeepSplats;
  for (const auto splats : {DeepSplats::Auto, DeepSplats::Two}) {
    ShadowRig rig(*ctx, set, s, 0, splats);
    const OpacityCapture c = rig.run(*ctx, glm::vec3(0.0f, 0.0f, 1.0f));
    std::size_t pile = 0, wrong = 0;
    for (std::uint32_t y = 0; y < 64; ++y)
      for (std::uint32_t x = 20; x < 56; ++x) {
        if (c.at(15, x, y) < 1000.0f) continue;
        ++pile;
        for (std::uint32_t i = 0; i < 16; ++i) wrong += c.at(i, x, y) != hp::gpu::OPACITY_SATURATED_ALPHA;
      }
    EXPECT_GE(pile, 30u) << "one splat: " << (splats == DeepSplats::Auto);
    EXPECT_EQ(wrong, 0u) << "one splat: " << (splats == DeepSplats::Auto);
  }
}

// Auto takes the compute path where its bins fit the device's maxStorageBufferRange and the graphics path
// where they do not (lavapipe: 128 MiB, so 2048^2's 256 MiB of bins do not); Compute asked for by name
// past the limit is refused up front, naming the limit.
TEST_F(VulkanTest, OpacityRasterAutoFallsBackToGraphicsWhereTheBinsExceedTheDevice) {
  for (std::uint32_t resolution : {512u, 2048u}) {
    OpacitySettings s;
    s.resolution = resolution;
    const bool fits = hp::compute::OpacityResolvePass::fits(*ctx, resolution);
    const hp::render::ShadowMaps automatic(*ctx, s);
    EXPECT_EQ(automatic.raster(), fits ? hp::render::OpacityRaster::Compute : hp::render::OpacityRaster::Graphics)
        << resolution;
    s.raster = hp::render::OpacityRaster::Graphics;
    EXPECT_EQ(hp::render::ShadowMaps(*ctx, s).raster(), hp::render::OpacityRaster::Graphics) << resolution;
    s.raster = hp::render::OpacityRaster::Compute;
    if (fits) {
      EXPECT_EQ(hp::render::ShadowMaps(*ctx, s).raster(), hp::render::OpacityRaster::Compute) << resolution;
      continue;
    }
    try {
      hp::render::ShadowMaps refused(*ctx, s);
      ADD_FAILURE() << "compute opacity maps accepted past maxStorageBufferRange at " << resolution;
    } catch (const hp::Error& e) {
      EXPECT_NE(std::string(e.what()).find("maxStorageBufferRange"), std::string::npos) << e.what();
    }
  }
  EXPECT_EQ(hp::render::parseOpacityRaster("auto"), hp::render::OpacityRaster::Auto);
  EXPECT_THROW(hp::render::parseOpacityRaster("splat"), hp::Error);
}

// Deep opacity maps (compute path): the slices start at each texel's first hair and are
// OPACITY_DEEP_FACTOR (4) times finer. Four layers of 40 strands at light depths 0, 0.05, 0.1 and 1
// (global slice coordinates 0, 0.8, 1.6, 16) are at deep coordinates 0, 3.2, 6.4 and 64 from the first:
// slices 1-16 hold the first layer, 4-16 the second, 7-16 the third, and the last slice also the fourth
// (it reaches to infinity); the last image layer holds s0 = 0 on the strands' rows and OPACITY_NO_HAIR
// elsewhere. The graphics path keeps global slices (settings().deep false).
TEST_F(VulkanTest, DeepOpacityMapsStartAtEachTexelsFirstHair) {
  StrandSet set;
  set.q = 4;
  for (float z : {0.0f, -0.05f, -0.1f, -1.0f})
    for (int j = 0; j < 40; ++j) set.addStraight({-0.5f, -0.5f + float(j) / 39.0f, z}, {0.5f, -0.5f + float(j) / 39.0f, z});
  OpacitySettings s = smallSettings(64, 0.25f);
  s.deep = true;
  s.raster = hp::render::OpacityRaster::Graphics;
  EXPECT_FALSE(ShadowRig(*ctx, set, s).maps->settings().deep);
  s.raster = hp::render::OpacityRaster::Compute;
  for (const auto splats : {hp::render::ShadowMaps::DeepSplats::Auto, hp::render::ShadowMaps::DeepSplats::Two}) {
    ShadowRig rig(*ctx, set, s, 0, splats);
    ASSERT_TRUE(rig.maps->settings().deep);
    const bool one = splats == hp::render::ShadowMaps::DeepSplats::Auto;
    EXPECT_EQ(rig.maps->resolvePass()->layout(),
              one ? hp::compute::OpacityBins::DeepFine : hp::compute::OpacityBins::DeepTwoSplats);
    const OpacityCapture c = rig.run(*ctx, glm::vec3(0.0f, 0.0f, 1.0f));
    const auto [count, ambiguous] = strandRows(c.light);
    std::size_t checked = 0, wrong = 0;
    for (std::uint32_t y = 0; y < 64; ++y) {
      if (ambiguous[y]) continue;
      for (std::uint32_t x = 5; x < 59; ++x) {
        const float s0 = c.firstHair[std::size_t(y) * 64 + x];
        if (count[y] == 0) {
          EXPECT_GE(s0, hp::gpu::OPACITY_NO_HAIR) << x << "," << y;
          continue;
        }
        EXPECT_NEAR(s0, 0.0f, 1e-4f) << x << "," << y;
        for (std::uint32_t i = 1; i <= 16; ++i) {
          const float expected =
              0.25f * count[y] * (1.0f + (i >= 4 ? 1.0f : 0.0f) + (i >= 7 ? 1.0f : 0.0f) + (i == 16 ? 1.0f : 0.0f));
          ++checked;
          if (std::abs(c.at(i - 1, x, y) - expected) > 1e-4f) ++wrong;
        }
      }
    }
    EXPECT_GT(checked, 16u * 54u * 30u) << "one splat: " << one;
    EXPECT_EQ(wrong, 0u) << "one splat: " << one;
  }
}

// The fine bins come in whole groups of OPACITY_FINE_GROUP texels (opacityFineBin), so a map whose texel
// count is no multiple of the group still holds every texel's bins; and at such a resolution (61^2) the
// one-splat deep maps of a random volume equal the two-splat ones where both are exact: each texel's first
// hair, and its last slice (every fragment behind it).
TEST(OpacityBins, FineBinsCoverEveryTexelOfAnyResolution) {
  using hp::compute::OpacityBins;
  using hp::compute::OpacityResolvePass;
  for (std::uint32_t resolution : {16u, 61u, 63u, 64u, 101u, 512u}) {
    const std::uint32_t texels = resolution * resolution;
    std::uint32_t last = 0;
    for (std::uint32_t t = texels - std::min(texels, 64u); t < texels; ++t)
      last = std::max(last, hp::gpu::opacityFineBin(t, hp::gpu::OPACITY_DEEP_BINS - 1u));
    EXPECT_LT(VkDeviceSize(last) * 4u, OpacityResolvePass::binBytes(resolution, OpacityBins::DeepFine)) << resolution;
  }
}

TEST_F(VulkanTest, DeepMapsInOneAndTwoSplatsAgreeOnTheFirstHairAndTheLastSlice) {
  const StrandSet set = tiltedVolume();
  OpacitySettings s = smallSettings(61, 0.1f);
  s.deep = true;
  s.raster = hp::render::OpacityRaster::Compute;
  const glm::vec3 light = glm::normalize(glm::vec3(0.3f, 0.8f, 0.5f));
  using DeepSplats = hp::render::ShadowMaps::DeepSplats;
  ShadowRig one(*ctx, set, s, 0, DeepSplats::Auto), two(*ctx, set, s, 0, DeepSplats::Two);
  ASSERT_EQ(one.maps->resolvePass()->layout(), hp::compute::OpacityBins::DeepFine);
  const OpacityCapture a = one.run(*ctx, light), b = two.run(*ctx, light);
  std::size_t hair = 0, wrong = 0;
  for (std::uint32_t y = 0; y < 61; ++y)
    for (std::uint32_t x = 0; x < 61; ++x) {
      const std::size_t t = std::size_t(y) * 61 + x;
      hair += b.firstHair[t] < hp::gpu::OPACITY_NO_HAIR;
      wrong += a.firstHair[t] != b.firstHair[t];
      wrong += std::abs(a.at(15, x, y) - b.at(15, x, y)) > 1e-4f * (1.0f + b.at(15, x, y));
    }
  EXPECT_GT(hair, 500u);
  EXPECT_EQ(wrong, 0u);
}

// Deep maps in one splat (OpacityBins::DeepFine) against two: a texel's first hair between fine bins. A
// marker strand at light depth 0 fixes the framing's near end (depth range [0, 1], s = 16 d); the 40 rows
// of four layers along x lie at s = 0.125, 0.3, 0.725 and 16, i.e. at fine coordinates f = 4 s = 0.5, 1.2,
// 2.9 and 64, so their first hair is f0 = 0.5 (share 0.5 of a fine bin). Two splats measure the deep
// coordinates exactly, 0, 0.7, 2.4, 63.5: slices 1-2 hold two layers, 3-15 three, 16 all four. One splat
// places slice i's end at f0 + i over the fine bins, taking half of the bin it ends in: slice 1 holds the
// first layer and half the second, slice 2 two and a half, 3-15 three, 16 all four. Both keep s0 exact.
TEST_F(VulkanTest, DeepMapsInOneSplatPlaceTheSlicesOverFineBins) {
  StrandSet set;
  set.q = 4;
  set.addStraight({-0.9f, -0.5f, 0.0f}, {-0.9f, 0.5f, 0.0f});  // the marker, left of the rows
  for (float s : {0.125f, 0.3f, 0.725f, 16.0f})
    for (int j = 0; j < 40; ++j)
      set.addStraight({-0.5f, -0.5f + float(j) / 39.0f, -s / 16.0f}, {0.5f, -0.5f + float(j) / 39.0f, -s / 16.0f});
  OpacitySettings settings = smallSettings(64, 0.25f);
  settings.deep = true;
  settings.raster = hp::render::OpacityRaster::Compute;
  using DeepSplats = hp::render::ShadowMaps::DeepSplats;
  for (const auto splats : {DeepSplats::Auto, DeepSplats::Two}) {
    ShadowRig rig(*ctx, set, settings, 0, splats);
    const bool fine = rig.maps->resolvePass()->layout() == hp::compute::OpacityBins::DeepFine;
    EXPECT_EQ(fine, splats == DeepSplats::Auto);
    const OpacityCapture c = rig.run(*ctx, glm::vec3(0.0f, 0.0f, 1.0f));
    ASSERT_NEAR(c.light.depthRange.x, 0.0f, 1e-6f);
    ASSERT_NEAR(c.light.depthRange.y, 1.0f, 1e-6f);
    const auto [count, ambiguous] = strandRows(c.light);
    // Texel columns well inside the rows' x extent, away from the marker.
    const int x0 = int(hp::test::texelAndSlice(c.light, 64, {-0.4, 0.0, 0.0}).x);
    const int x1 = int(hp::test::texelAndSlice(c.light, 64, {0.4, 0.0, 0.0}).x);
    ASSERT_GT(x1 - x0, 30);
    // Layers per slice i (1-based): one splat, two splats.
    auto layers = [&](std::uint32_t i) {
      if (i == 16) return 4.0f;
      if (i >= 3) return 3.0f;
      return fine ? float(i) + 0.5f : 2.0f;
    };
    std::size_t checked = 0, wrong = 0, wrongFirst = 0;
    for (std::uint32_t y = 0; y < 64; ++y) {
      if (ambiguous[y] || count[y] == 0) continue;
      for (int x = x0; x <= x1; ++x) {
        wrongFirst += std::abs(c.firstHair[std::size_t(y) * 64 + x] - 0.125f) > 1e-4f;
        for (std::uint32_t i = 1; i <= 16; ++i) {
          ++checked;
          if (std::abs(c.at(i - 1, x, y) - 0.25f * count[y] * layers(i)) > 1e-4f) ++wrong;
        }
      }
    }
    EXPECT_GT(checked, 16u * 30u * 30u) << fine;
    EXPECT_EQ(wrong, 0u) << "one splat: " << fine;
    EXPECT_EQ(wrongFirst, 0u) << "one splat: " << fine;
  }
}
