// An offscreen draw with dynamic rendering, read back and checked pixel-exactly: a rectangle whose
// edges lie on pixel boundaries covers exactly the pixels whose centres are inside it.
#include <gtest/gtest.h>

#include "engine/vk/descriptors.h"
#include "engine/vk/pipeline.h"
#include "engine/vk/submit.h"
#include "engine/vk/transfer.h"
#include "shaders/shared/selftest.h"
#include "tests/support/color_pass.h"
#include "tests/support/vk_fixture.h"

using namespace hp::vk;
using hp::test::VulkanTest;

TEST_F(VulkanTest, DynamicRenderingDrawIsPixelExact) {
  const std::uint32_t w = 64, h = 48;
  const glm::vec4 rect{10, 8, 40, 30};  // x0, y0, x1, y1 in pixels (y down)
  std::vector<glm::vec4> vertices = {{rect.x, rect.y, 0, 1}, {rect.z, rect.y, 0, 1}, {rect.z, rect.w, 0, 1},
                                     {rect.x, rect.y, 0, 1}, {rect.z, rect.w, 0, 1}, {rect.x, rect.w, 0, 1}};
  Buffer vbuf(*ctx, vertices.size() * sizeof(glm::vec4),
              VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryKind::DeviceLocal,
              "rect vertices");
  upload<glm::vec4>(*ctx, vbuf, vertices, BufferUse::VertexRead);
  const Binding bindings[] = {{hp::gpu::DRAW_BINDING_VERTICES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_SHADER_STAGE_VERTEX_BIT}};
  DescriptorSet set(*ctx, bindings, "flat draw");
  set.writeStorageBuffer(hp::gpu::DRAW_BINDING_VERTICES, vbuf.handle());

  Image target(*ctx, {w, h, 1, VK_FORMAT_R8G8B8A8_UNORM,
                      VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT, VK_SAMPLE_COUNT_1_BIT,
                      "flat target"});
  GraphicsPipelineDesc desc;
  desc.vertexShader = "selftest_flat.vert";
  desc.fragmentShader = "selftest_flat.frag";
  desc.colorFormats = {VK_FORMAT_R8G8B8A8_UNORM};
  desc.sets = {set.layout()};
  desc.pushSize = sizeof(hp::gpu::FlatDrawPush);
  desc.name = "flat draw";
  GraphicsPipeline pipeline(*ctx, desc);

  submitAndWait(*ctx, [&](VkCommandBuffer cmd) {
    imageBarrier(*ctx, cmd, target.handle(), target.aspect(), ImageUse::Undefined, ImageUse::ColorAttachment);
    hp::test::beginClearedColorPass(*ctx, cmd, target.view(), {w, h}, {{0.0f, 0.0f, 1.0f, 1.0f}});
    pipeline.bind(cmd, set.set(), {w, h});
    pipeline.push(cmd, hp::gpu::FlatDrawPush{{1.0f, 0.5f, 0.0f, 1.0f}, {float(w), float(h)}, {}});
    ctx->fn().vkCmdDraw(cmd, 6, 1, 0, 0);
    ctx->fn().vkCmdEndRendering(cmd);
  }, "flat draw");

  auto pixels = readbackImage(*ctx, target, ImageUse::ColorAttachment);
  std::size_t wrong = 0;
  for (std::uint32_t y = 0; y < h; ++y)
    for (std::uint32_t x = 0; x < w; ++x) {
      const auto* p = reinterpret_cast<const std::uint8_t*>(pixels.data()) + 4 * (y * w + x);
      bool inside = x >= rect.x && x < rect.z && y >= rect.y && y < rect.w;
      std::uint8_t expect[4] = {inside ? std::uint8_t(255) : std::uint8_t(0), inside ? std::uint8_t(128) : std::uint8_t(0),
                                inside ? std::uint8_t(0) : std::uint8_t(255), 255};
      // 0.5 in UNORM8 is 127.5: the spec allows either neighbour, so G accepts 127 or 128.
      bool ok = p[0] == expect[0] && p[2] == expect[2] && p[3] == expect[3] &&
                (inside ? (p[1] == 127 || p[1] == 128) : p[1] == 0);
      wrong += ok ? 0 : 1;
    }
  EXPECT_EQ(wrong, 0u);
}
