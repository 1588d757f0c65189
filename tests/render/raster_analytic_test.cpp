// The compute rasterizer against analytic references (docs/THEORY.md §7.1): the coverage formula against a
// supersampled pixel on the CPU; on the device, one straight strand of known width at known angles
// (per-pixel coverage within 2% of a supersampled reference), two crossing strands (the front-to-back
// composite equals the analytic "over" within 1%), parallel strands (their union, not the independent
// "over"), a strand behind the head's depth hidden, and the tip taper; the overlap mask's rows against
// its samples.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "engine/core/error.h"
#include "engine/vk/transfer.h"
#include "shaders/shared/raster.h"
#include "tests/render/raster_rig.h"
#include "tests/support/vk_fixture.h"

using hp::test::VulkanTest;

namespace {
constexpr VkExtent2D kExtent{64, 48};
constexpr float kFov = 0.8f;
constexpr std::uint32_t kQ = 4;

using hp::test::PixelStrand;

void uploadStrands(const hp::vk::Context& ctx, const hp::compute::StrandBuffers& buffers,
                   const hp::CameraMatrices& camera, const std::vector<PixelStrand>& strands) {
  hp::test::uploadPixelStrands(ctx, buffers, camera, kExtent, strands);
}

std::unique_ptr<hp::compute::StrandBuffers> makeStrands(const hp::vk::Context& ctx, const hp::CameraMatrices& camera,
                                                        const std::vector<PixelStrand>& strands) {
  return hp::test::makePixelStrands(ctx, camera, kExtent, strands, kQ);
}

hp::render::LookSettings rigLook(const hp::CameraMatrices& camera, float tipFraction = 1.0f) {
  hp::render::LookSettings look;
  look.strandWidth = 2.0f * std::tan(0.5f * camera.fovY) / float(kExtent.height);  // one pixel at unit depth
  look.tipWidthFraction = tipFraction;
  return look;
}

// Ambient only: every strand's radiance is skyAlbedo * ambient * RENDER_HAIR_SKY_VISIBILITY * colorScale,
// constant along it.
hp::LightSpec darkLight() {
  hp::LightSpec light;
  light.intensity = 0.0f;
  return light;
}

// Fraction of the pixel (px, py) within half `width(t)` of the line a-b, on an n x n grid of samples.
double supersampled(glm::dvec2 a, glm::dvec2 b, double widthA, double widthB, int px, int py, int n) {
  const glm::dvec2 dir = glm::normalize(b - a);
  const glm::dvec2 normal(-dir.y, dir.x);
  const double length = glm::length(b - a);
  int inside = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const glm::dvec2 p(px + (i + 0.5) / n, py + (j + 0.5) / n);
      const double t = glm::dot(p - a, dir) / length;
      const double w = widthA + (widthB - widthA) * t;
      if (std::abs(glm::dot(p - a, normal)) <= 0.5 * w) ++inside;
    }
  return double(inside) / double(n * n);
}

// Exact coverage of an axis-aligned band: the overlap of [d - w/2, d + w/2] with the pixel.
double boxCoverage(double d, double w) {
  return std::max(0.0, std::min(d + 0.5 * w, 0.5) - std::max(d - 0.5 * w, -0.5));
}

std::size_t at(int x, int y) { return std::size_t(y) * kExtent.width + x; }
}  // namespace

// A full list's share per tile (shared/raster.h rasterTileShare, what raster_scan_tiles.comp keeps): over
// frames of many tiles, small and full, and totals from just over the capacity to 30 times it, every asking
// tile keeps at least one entry and at most its own, and the tiles together stay within the capacity; where
// the total fits, every tile keeps all.
TEST(RasterLists, AFullListsShareKeepsEveryTileAnEntryAndFitsTheCapacity) {
  std::uint32_t seed = 12345u;
  const auto next = [&] { return seed = seed * 1664525u + 1013904223u; };
  for (int frame = 0; frame < 200; ++frame) {
    std::vector<std::uint32_t> budgeted(1 + next() % 40000);
    std::uint64_t total = 0;
    for (std::uint32_t& b : budgeted) {
      const std::uint32_t kind = next() % 10;  // sparse edges, ordinary tiles and a few at the 16,384 budget
      b = kind < 3 ? 1 + next() % 3 : kind < 9 ? next() % 600 : 16384;
      total += b;
    }
    const auto asking = std::uint32_t(std::count_if(budgeted.begin(), budgeted.end(), [](std::uint32_t b) { return b > 0; }));
    const double fraction = frame % 4 == 0 ? 1.0 : 0.033 + (next() % 1000) / 1000.0 * 0.96;
    const auto capacity = std::max<std::uint32_t>(std::uint32_t(double(total) * fraction), 16u * std::uint32_t(budgeted.size()));
    std::uint64_t kept = 0;
    for (const std::uint32_t b : budgeted) {
      const std::uint32_t k = hp::gpu::rasterTileShare(b, std::uint32_t(total), asking, capacity);
      ASSERT_LE(k, b);
      if (b > 0) ASSERT_GE(k, 1u);
      if (total <= capacity) ASSERT_EQ(k, b);
      kept += k;
    }
    ASSERT_LE(kept, std::uint64_t(capacity)) << "frame " << frame;
    // Little left unused: each tile's share rounds down by less than one entry, and the factor takes 1e-5.
    if (total > capacity) EXPECT_GE(kept + asking + capacity / 50000, std::uint64_t(capacity)) << "frame " << frame;
  }
}

TEST(RasterCoverage, BandCoverageIsTheExactPixelAreaAtAnyAngle) {
  for (double deg : {0.0, 10.0, 30.0, 45.0, 72.0, 90.0, 135.0})
    for (double w : {0.2, 0.7, 1.0, 1.8, 3.0})
      for (double d : {-1.2, -0.6, -0.25, 0.0, 0.1, 0.45, 0.9}) {
        const double rad = deg * 3.14159265358979 / 180.0;
        const glm::dvec2 n(-std::sin(rad), std::cos(rad));
        const glm::dvec2 centre(0.5, 0.5);
        const glm::dvec2 a = centre + d * n - 5.0 * glm::dvec2(std::cos(rad), std::sin(rad));
        const glm::dvec2 b = centre + d * n + 5.0 * glm::dvec2(std::cos(rad), std::sin(rad));
        const double reference = supersampled(a, b, w, w, 0, 0, 400);
        const float coverage = hp::gpu::rasterBandCoverage(float(d), float(w), float(n.x), float(n.y));
        EXPECT_NEAR(coverage, reference, 0.004) << deg << " deg, w " << w << ", d " << d;
      }
}

TEST(RasterCoverage, BandMaskRowsAreTheSamplesInsideTheBand) {
  // The overlap mask's rows against testing each of the 8 x 8 samples, for bands at many angles,
  // widths and offsets (samples within 1e-4 of the band's edge are not asserted: float rounding).
  int checked = 0;
  for (int angle = 0; angle < 180; angle += 7)
    for (float w : {0.05f, 0.1f, 0.3f, 0.8f, 1.7f})
      for (float d = -1.2f; d <= 1.2f; d += 0.0731f) {
        const float rad = glm::radians(float(angle));
        const glm::vec2 n(std::cos(rad), std::sin(rad));
        const glm::uvec2 mask = hp::gpu::rasterBandMask(d, w, n.x, n.y);
        for (std::uint32_t row = 0; row < hp::gpu::RASTER_MASK_SIDE; ++row) {
          const std::uint32_t bits = (mask[row >> 2u] >> ((row & 3u) * 8u)) & 0xFFu;  // row r: byte r % 4 of word r / 4
          for (std::uint32_t i = 0; i < hp::gpu::RASTER_MASK_SIDE; ++i) {
            const glm::vec2 s((i + 0.5f) / 8.0f - 0.5f, (row + 0.5f) / 8.0f - 0.5f);
            const float edge = std::abs(d + glm::dot(s, n)) - 0.5f * w;
            if (std::abs(edge) < 1e-4f) continue;
            ASSERT_EQ((bits >> i) & 1u, edge < 0.0f ? 1u : 0u) << angle << " deg, w " << w << ", d " << d << ", row " << row;
            ++checked;
          }
        }
      }
  EXPECT_GT(checked, 100000);
}

TEST(RasterCoverage, VisibleShareIsIndependenceCorrectedByTheSamplesOverlap) {
  using hp::gpu::rasterVisibleShare;
  EXPECT_FLOAT_EQ(rasterVisibleShare(0u, 10u, 0u, 0.3f), 0.7f);   // no samples: independence
  EXPECT_FLOAT_EQ(rasterVisibleShare(8u, 0u, 0u, 0.0f), 1.0f);    // nothing in front
  EXPECT_FLOAT_EQ(rasterVisibleShare(8u, 8u, 8u, 0.125f), 0.0f);  // the same samples: hidden
  EXPECT_FLOAT_EQ(rasterVisibleShare(8u, 8u, 0u, 0.125f), 1.0f);  // disjoint: all visible
  // A row crossing a column: 1 of its 8 samples covered, as independence predicts (8 / 64).
  EXPECT_FLOAT_EQ(rasterVisibleShare(8u, 8u, 1u, 0.125f), 0.875f);
  EXPECT_GE(rasterVisibleShare(64u, 8u, 8u, 0.9f), 0.0f);          // never negative
}

TEST_F(VulkanTest, OneStrandCoversEachPixelByItsAreaWithinTwoPercent) {
  const hp::CameraMatrices camera = hp::test::rigCamera(kExtent, kFov);
  const glm::vec2 centre(31.3f, 23.6f);
  // One rig; each case rewrites its one strand.
  auto buffers = makeStrands(*ctx, camera, {PixelStrand{{0.0f, 0.0f}, {1.0f, 1.0f}}});
  hp::test::RasterRig rig(*ctx, *buffers, kExtent, camera, rigLook(camera), darkLight());
  for (float deg : {0.0f, 17.0f, 30.0f, 45.0f, 63.0f, 90.0f, 124.0f})
    for (float width : {0.35f, 1.0f, 2.6f}) {
      const float rad = glm::radians(deg);
      const glm::vec2 dir(std::cos(rad), std::sin(rad));
      PixelStrand strand{centre - 60.0f * dir, centre + 60.0f * dir, 1.0f, width, 1.0f};
      uploadStrands(*ctx, *buffers, camera, {strand});
      rig.run();
      const auto image = rig.image();
      double worst = 0.0;
      for (int y = 0; y < int(kExtent.height); ++y)
        for (int x = 0; x < int(kExtent.width); ++x) {
          // 96^2 samples: the reference itself is good to ~1/96 at a band edge.
          const double reference = supersampled(strand.from, strand.to, width, width, x, y, 96);
          worst = std::max(worst, std::abs(double(image[at(x, y)].a) - reference));
        }
      EXPECT_LE(worst, 0.02) << deg << " deg, " << width << " px";
    }
}

TEST_F(VulkanTest, TheTipTaperNarrowsTheCoverageAlongTheStrand) {
  const hp::CameraMatrices camera = hp::test::rigCamera(kExtent, kFov);
  // Root at the left edge, tip at the right: 3 px at the root, 0.35 x 3 px at the tip.
  PixelStrand strand{{2.0f, 20.3f}, {62.0f, 20.3f}, 1.0f, 3.0f, 1.0f};
  auto buffers = makeStrands(*ctx, camera, {strand});
  hp::test::RasterRig rig(*ctx, *buffers, kExtent, camera, rigLook(camera, 0.35f), darkLight());
  rig.run();
  const auto image = rig.image();
  for (int x = 4; x < 60; x += 5) {
    double column = 0.0;
    for (int y = 0; y < int(kExtent.height); ++y) column += image[at(x, y)].a;
    const double t = (x + 0.5 - 2.0) / 60.0;
    EXPECT_NEAR(column, 3.0 * (1.0 + (0.35 - 1.0) * t), 0.02) << "column " << x;
  }
}

TEST_F(VulkanTest, CrossingStrandsCompositeFrontToBackAsTheAnalyticOver) {
  const hp::CameraMatrices camera = hp::test::rigCamera(kExtent, kFov);
  // Front: horizontal, 0.7 px at depth 1; back: vertical, 1.6 px at depth 1.5, a different lightness.
  const PixelStrand front{{-10.0f, 20.3f}, {80.0f, 20.3f}, 1.0f, 0.7f, 1.2f};
  const PixelStrand back{{30.6f, -10.0f}, {30.6f, 60.0f}, 1.5f, 1.6f, 0.8f};
  auto buffers = makeStrands(*ctx, camera, {back, front});  // list order must not matter
  hp::test::RasterRig rig(*ctx, *buffers, kExtent, camera, rigLook(camera), darkLight());
  rig.run();
  const auto image = rig.image();
  const float ambient = rigLook(camera).ambient;  // a uniform sky: the environment's light in every direction
  const glm::vec3 base = glm::vec3(rig.marschner.params().skyAlbedo) * (ambient * hp::gpu::RENDER_HAIR_SKY_VISIBILITY);
  int checked = 0;
  for (int y = 18; y <= 22; ++y)
    for (int x = 28; x <= 33; ++x) {
      const double aF = boxCoverage(y + 0.5 - 20.3, 0.7);
      const double aB = boxCoverage(x + 0.5 - 30.6, 1.6);
      const double alpha = aF + (1.0 - aF) * aB;
      if (alpha < 0.05) continue;
      ++checked;
      EXPECT_NEAR(image[at(x, y)].a, alpha, 0.01 * alpha) << x << "," << y;
      for (int c = 0; c < 3; ++c) {
        const double expected = aF * 1.2 * base[c] + (1.0 - aF) * aB * 0.8 * base[c];
        EXPECT_NEAR(image[at(x, y)][c], expected, 0.01 * expected) << x << "," << y << " channel " << c;
      }
    }
  EXPECT_GE(checked, 8);
}

TEST_F(VulkanTest, ParallelStrandsCoverTheirUnionNotTheirIndependentOver) {
  // Strands of a sheet seen edge-on: two at the same place cover what one does (alpha compositing's
  // independent "over" would give 1 - (1 - a)^2), two side by side within a pixel cover the sum.
  const hp::CameraMatrices camera = hp::test::rigCamera(kExtent, kFov);
  const float y = 20.3f, width = 0.4f;
  auto measure = [&](const std::vector<PixelStrand>& strands) {
    auto buffers = makeStrands(*ctx, camera, strands);
    hp::test::RasterRig rig(*ctx, *buffers, kExtent, camera, rigLook(camera), darkLight());
    rig.run();
    return rig.image();
  };
  const auto one = measure({{{-10.0f, y}, {80.0f, y}, 1.0f, width, 1.0f}});
  const auto same = measure({{{-10.0f, y}, {80.0f, y}, 1.0f, width, 1.0f}, {{-10.0f, y}, {80.0f, y}, 1.2f, width, 1.0f}});
  const auto apart = measure({{{-10.0f, y - 0.22f}, {80.0f, y - 0.22f}, 1.0f, width, 1.0f},
                              {{-10.0f, y + 0.22f}, {80.0f, y + 0.22f}, 1.2f, width, 1.0f}});
  // Row 20 holds all of the single strand and of the lower neighbour, part of the upper one:
  // union 0.28 + 0.4 = 0.68, where independence would give 0.57.
  const double a = boxCoverage(y - 20.5, width);
  const double union2 = boxCoverage(y - 0.22 - 20.5, width) + boxCoverage(y + 0.22 - 20.5, width);
  for (int x = 5; x < 60; x += 6) {
    ASSERT_NEAR(one[at(x, 20)].a, a, 0.01) << "column " << x;
    EXPECT_NEAR(same[at(x, 20)].a, a, 0.02) << "coincident strands, column " << x;
    EXPECT_NEAR(apart[at(x, 20)].a, union2, 0.02) << "side by side, column " << x;
  }
}

TEST_F(VulkanTest, AStrandBehindTheHeadsDepthIsHidden) {
  const hp::CameraMatrices camera = hp::test::rigCamera(kExtent, kFov);
  const PixelStrand front{{-10.0f, 20.5f}, {80.0f, 20.5f}, 1.0f, 1.0f, 1.0f};
  const PixelStrand back{{30.5f, -10.0f}, {30.5f, 60.0f}, 1.5f, 1.0f, 1.0f};
  auto buffers = makeStrands(*ctx, camera, {front, back});
  hp::test::RasterRig rig(*ctx, *buffers, kExtent, camera, rigLook(camera), darkLight());
  rig.run(hp::test::ndcDepth(camera, 1.25f));  // the "head" between the two strands
  const auto image = rig.image();
  for (int y = 0; y < int(kExtent.height); ++y) {
    if (y != 20) {
      EXPECT_EQ(image[at(30, y)].a, 0.0f) << "back strand shows at row " << y;
    }
  }
  for (int x = 0; x < int(kExtent.width); ++x) EXPECT_NEAR(image[at(x, 20)].a, 1.0f, 1e-3) << "front strand, column " << x;
  rig.run(1.0f);  // nothing drawn: both show
  EXPECT_NEAR(rig.image()[at(30, 5)].a, 1.0f, 1e-3);
}

// The head depth's sample count is refused, by its message, unless a power of two up to
// RASTER_MAX_HEAD_SAMPLES (the fine pass's near mask and loops are sized by it).
TEST_F(VulkanTest, ARasterRefusesAHeadSampleCountItCannotRead) {
  const hp::CameraMatrices camera = hp::test::rigCamera(kExtent, kFov);
  auto buffers = makeStrands(*ctx, camera, {PixelStrand{{0.0f, 0.0f}, {1.0f, 1.0f}}});
  const hp::compute::ShadingWriter unused = [](const hp::vk::DescriptorSet&) {};
  for (std::uint32_t samples : {0u, 3u, 2u * hp::gpu::RASTER_MAX_HEAD_SAMPLES}) {
    try {
      hp::compute::StrandRasterPass pass(*ctx, *buffers, unused, kExtent, {}, samples);
      ADD_FAILURE() << samples << " head samples were accepted";
    } catch (const hp::Error& e) {
      EXPECT_NE(std::string(e.what()).find("sample count must be a power of two in [1, 16], got " +
                                           std::to_string(samples)),
                std::string::npos)
          << e.what();
    }
  }
}

// A strand of zero length (every segment a point) is listed by the bin pass but draws nothing, in both
// walks of the fine pass (compute/raster/strand_raster_pass.h FineWalk), leaves no NaN, and leaves the
// strand beside it as it is. (The fine pass skips such segments; without the skip its 0/0 would still give
// no coverage on lavapipe, whose max drops a NaN operand, but SPIR-V leaves that undefined.)
TEST_F(VulkanTest, AZeroLengthStrandDrawsNothingInEitherFineWalk) {
  const hp::CameraMatrices camera = hp::test::rigCamera(kExtent, kFov);
  const PixelStrand point{{20.3f, 20.6f}, {20.3f, 20.6f}, 1.0f, 2.0f, 1.0f};
  const PixelStrand line{{40.0f, 4.0f}, {44.0f, 44.0f}, 1.0f, 1.0f, 1.0f};
  auto buffers = makeStrands(*ctx, camera, {point, line});
  for (auto walk : {hp::compute::FineWalk::Direct, hp::compute::FineWalk::Staged}) {
    hp::compute::RasterSettings settings;
    settings.fineWalk = walk;
    hp::test::RasterRig rig(*ctx, *buffers, kExtent, camera, rigLook(camera), darkLight(), settings);
    rig.run();
    const auto image = rig.image();
    double around = 0.0, drawn = 0.0;
    for (int y = 0; y < int(kExtent.height); ++y)
      for (int x = 0; x < int(kExtent.width); ++x) {
        const glm::vec4 p = image[at(x, y)];
        ASSERT_TRUE(std::isfinite(p.r) && std::isfinite(p.g) && std::isfinite(p.b) && std::isfinite(p.a)) << x << "," << y;
        if (std::abs(x - 20) <= 3 && std::abs(y - 20) <= 3) around += p.a;
        drawn += p.a;
      }
    const bool direct = walk == hp::compute::FineWalk::Direct;
    EXPECT_EQ(around, 0.0) << (direct ? "direct" : "staged") << " walk: the point drew";
    EXPECT_NEAR(drawn, 40.2, 2.0) << (direct ? "direct" : "staged") << " walk: the line's coverage (~its length in pixels)";
  }
}
