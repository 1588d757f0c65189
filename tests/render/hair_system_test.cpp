// The embedding facade refuses what an application could hand it wrongly, before anything reaches the device.
#include <gtest/gtest.h>

#include "engine/core/error.h"
#include "engine/core/hair/default_head.h"
#include "samples/tools/hair_system.h"
#include "engine/vk/submit.h"
#include "tests/support/vk_fixture.h"

using namespace hp;
using hp::test::VulkanTest;

namespace {
HairAsset smallHead() {
  DensityOptions density;
  density.totalStrands = 500;
  return buildDefaultHeadAsset(defaultHeadGrowth(), density);
}
}  // namespace

TEST_F(VulkanTest, HairSystemRefusesSampleCountsItsCoverageMaskCannotHold) {
  HairSystemSettings settings;
  settings.formats.samples = VK_SAMPLE_COUNT_32_BIT;
  try {
    HairSystem hair(*ctx, smallHead(), settings);
    FAIL() << "accepted 32 samples";
  } catch (const hp::Error& e) {
    EXPECT_NE(std::string(e.what()).find("samples"), std::string::npos) << e.what();
  }
}

TEST_F(VulkanTest, HairSystemRefusesADegenerateView) {
  HairSystem hair(*ctx, smallHead(), HairSystemSettings{});
  DrawView view;
  view.extent = {64, 64};
  view.lights.resize(2);
  view.lights[1].direction = {0.0f, 0.0f, 0.0f};
  try {
    vk::submitAndWait(*ctx, [&](VkCommandBuffer cmd) { hair.recordPrepareDraw(cmd, view); }, "bad light");
    ADD_FAILURE() << "a zero light direction was accepted";
  } catch (const hp::Error& e) {
    EXPECT_NE(std::string(e.what()).find("lights[1]: light direction"), std::string::npos) << e.what();
  }
  view.lights.assign(9, LightSpec{});
  EXPECT_THROW(vk::submitAndWait(*ctx, [&](VkCommandBuffer cmd) { hair.recordPrepareDraw(cmd, view); }, "9 lights"),
               hp::Error);
  view.lights = {LightSpec{}};
  view.extent = {0, 64};
  EXPECT_THROW(vk::submitAndWait(*ctx, [&](VkCommandBuffer cmd) { hair.recordPrepareDraw(cmd, view); }, "bad extent"),
               hp::Error);
  view.extent = {64, 64};
  view.camera.proj[0][0] = std::nanf("");
  EXPECT_THROW(vk::submitAndWait(*ctx, [&](VkCommandBuffer cmd) { hair.recordPrepareDraw(cmd, view); }, "bad matrix"),
               hp::Error);
}
