// The opacity lookup (hairpipeShadowAlpha, shaders/public/hairpipe/hair_shadows.glsl) on the device against its definition on the CPU: alpha at
// slice coordinate d is sum over the 16 slices i of max(0, 1 - |d - i|) alpha_i, d = s - bias (global maps)
// or (s - s0) x OPACITY_DEEP_FACTOR - bias (deep maps), clamped to [0, 16], and 0 in front of the maps
// (s < 0). The lookup fetches only the layers whose weights can be non-zero and none in front of the first
// slice; this checks that those shortcuts leave the sum as it is, across every layer boundary.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "engine/vk/buffer.h"
#include "engine/vk/descriptors.h"
#include "engine/vk/image.h"
#include "engine/vk/pipeline.h"
#include "engine/vk/submit.h"
#include "engine/vk/transfer.h"
#include "shaders/shared/opacity.h"
#include "shaders/shared/selftest.h"
#include "tests/support/vk_fixture.h"

using namespace hp::vk;
using hp::test::VulkanTest;

namespace {
constexpr float kFirstHair = 2.25f;  // s0 of the deep map's texel

float sliceAlpha(std::uint32_t i) { return 0.37f + 0.1f * float(i) + 0.013f * float(i * i); }  // slice i = 1..16

// The definition, in double precision.
double expected(float s, float bias, bool deep) {
  if (s < 0.0f) return 0.0;
  double d = deep ? (double(s) - kFirstHair) * hp::gpu::OPACITY_DEEP_FACTOR - bias : double(s) - bias;
  d = std::clamp(d, 0.0, double(hp::gpu::OPACITY_SLICES));
  double alpha = 0.0;
  for (std::uint32_t i = 1; i <= hp::gpu::OPACITY_SLICES; ++i) alpha += std::max(0.0, 1.0 - std::abs(d - i)) * sliceAlpha(i);
  return alpha;
}

const Binding kBindings[] = {
    {hp::gpu::LOOKUP_BINDING_MAPS, kSampled, kCompute},
    {hp::gpu::LOOKUP_BINDING_QUERIES, kStorage, kCompute},
    {hp::gpu::LOOKUP_BINDING_RESULTS, kStorage, kCompute},
};
}  // namespace

TEST_F(VulkanTest, OpacityLookupEqualsTheSumOverAllSlices) {
  ImageDesc desc;
  desc.layers = hp::gpu::OPACITY_LAYERS;
  desc.format = VK_FORMAT_R32G32B32A32_SFLOAT;
  desc.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  desc.arrayView = true;
  desc.name = "lookup test maps";
  Image maps(*ctx, desc);
  std::vector<float> texels(4 * hp::gpu::OPACITY_LAYERS, 0.0f);
  for (std::uint32_t i = 1; i <= hp::gpu::OPACITY_SLICES; ++i) texels[i - 1] = sliceAlpha(i);
  texels[4 * hp::gpu::OPACITY_TARGETS] = kFirstHair;  // the deep maps' first-hair layer
  uploadImage(*ctx, maps, std::as_bytes(std::span<const float>(texels)), ImageUse::ComputeSampled);
  Sampler sampler(*ctx, "lookup test sampler");

  // Slice coordinates over the whole range and either side of it, every integer and layer boundary among them.
  std::vector<glm::vec4> queries;
  for (int deep = 0; deep < 2; ++deep)
    for (float bias : {0.0f, 0.25f, 1.0f})
      for (int k = -40; k <= 720; ++k) queries.emplace_back(float(k) / 40.0f, bias, float(deep), 0.0f);
  for (float s : {4.0f, 8.0f, 12.0f, 16.0f})
    for (float e : {-1e-4f, 1e-4f}) queries.emplace_back(s + e, 0.0f, 0.0f, 0.0f);
  const auto count = std::uint32_t(queries.size());
  Buffer queryBuffer(*ctx, count * sizeof(glm::vec4), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                     MemoryKind::DeviceLocal, "lookup queries");
  upload<glm::vec4>(*ctx, queryBuffer, queries, BufferUse::ComputeRead);
  Buffer results(*ctx, count * sizeof(float), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                 MemoryKind::DeviceLocal, "lookup results");

  DescriptorSet set(*ctx, kBindings, "lookup test");
  set.writeSampledImage(hp::gpu::LOOKUP_BINDING_MAPS, maps.view(), sampler.handle());
  set.writeStorageBuffer(hp::gpu::LOOKUP_BINDING_QUERIES, queryBuffer.handle());
  set.writeStorageBuffer(hp::gpu::LOOKUP_BINDING_RESULTS, results.handle());
  ComputePipeline lookup(*ctx, "selftest_opacity_lookup.comp", hp::gpu::LOOKUP_WORKGROUP_SIZE, {set.layout()},
                         sizeof(hp::gpu::ScanPush), "opacity lookup test");
  submitAndWait(*ctx, [&](VkCommandBuffer cmd) {
    lookup.bind(cmd, set.set());
    lookup.push(cmd, hp::gpu::ScanPush{count});
    lookup.dispatch(cmd, count);
  }, "opacity lookup test");
  const std::vector<float> alpha = readback<float>(*ctx, results, BufferUse::ComputeWrite, count);

  double worst = 0.0;
  std::size_t nonZero = 0;
  for (std::uint32_t q = 0; q < count; ++q) {
    const double want = expected(queries[q].x, queries[q].y, queries[q].z > 0.5f);
    const double error = std::abs(double(alpha[q]) - want);
    worst = std::max(worst, error);
    nonZero += want > 0.0;
    EXPECT_LE(error, 1e-5 * std::max(1.0, want)) << "s " << queries[q].x << ", bias " << queries[q].y
                                                 << (queries[q].z > 0.5f ? ", deep" : ", global");
  }
  std::printf("%u lookups, %zu of them non-zero: largest difference %.2g\n", count, nonZero, worst);
  EXPECT_GT(nonZero, count / 2);
}
