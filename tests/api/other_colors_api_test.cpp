// AttachmentFormats::otherColors through the public headers: an adopted device whose application did not
// enable independentBlend is refused by name, one that did is taken (here: a headless context's device,
// adopted a second time with either answer; the images drawn are checked in
// tests/render/other_color_attachments_test.cpp). RendererSettings::velocityOutput reaches the Renderer: refused
// by field where it names no attachment or the raster writes no motion, taken with the compute raster.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <dlfcn.h>

#include <optional>
#include <string>

#include "hairpipe/hairpipe.h"
#include "tests/api/validated_context.h"

namespace {
using ::testing::HasSubstr;

TEST(OtherColorsApi, AnAdoptedDeviceMustSayItEnabledIndependentBlend) {
  std::optional<hairpipe::Context> headless;
  ASSERT_NO_FATAL_FAILURE(hairpipe::test::createValidatedContext(headless));
  void* loader = dlopen("libvulkan.so.1", RTLD_NOW | RTLD_LOCAL);  // the loader the headless context uses
  ASSERT_NE(loader, nullptr);
  const auto getInstanceProcAddr = reinterpret_cast<PFN_vkGetInstanceProcAddr>(dlsym(loader, "vkGetInstanceProcAddr"));
  hairpipe::RendererSettings s;
  s.formats = {VK_FORMAT_R16G16B16A16_SFLOAT, VK_FORMAT_D32_SFLOAT, VK_SAMPLE_COUNT_1_BIT};
  s.formats.otherColors = {VK_FORMAT_R16G16_SFLOAT};
  for (const bool enabled : {false, true}) {
    hairpipe::DeviceHandles handles{getInstanceProcAddr, headless->instance(), headless->physicalDevice(),
                                    headless->device(), headless->queueFamily(), headless->queue(), false};
    handles.independentBlendEnabled = enabled;  // the headless device has it: either answer is the test's
    hairpipe::Result<hairpipe::Context> adopted = hairpipe::Context::adopt(handles);
    ASSERT_TRUE(adopted.ok()) << adopted.message();
    const hairpipe::Result<hairpipe::Renderer> renderer = hairpipe::Renderer::create(adopted.value(), s);
    if (enabled) {
      EXPECT_TRUE(renderer.ok()) << renderer.message();
    } else {
      EXPECT_FALSE(renderer.ok());
      EXPECT_THAT(renderer.message(), HasSubstr("RendererSettings.formats.otherColors: the device's independentBlend "
                                                "feature is not enabled"));
    }
  }
  dlclose(loader);
  hairpipe::test::expectIdleAndSilent(*headless);
}

TEST(OtherColorsApi, AVelocityOutputNeedsOneOfTheOtherColoursAndTheComputeRastersMotion) {
  std::optional<hairpipe::Context> context;
  ASSERT_NO_FATAL_FAILURE(hairpipe::test::createValidatedContext(context));
  hairpipe::RendererSettings s;
  s.formats = {VK_FORMAT_R16G16B16A16_SFLOAT, VK_FORMAT_D32_SFLOAT, VK_SAMPLE_COUNT_1_BIT};
  s.formats.otherColors = {VK_FORMAT_R16G16_SFLOAT};
  s.raster = hairpipe::RasterMode::Compute;
  s.motionVectors = true;
  s.velocityOutput.attachment = 1;
  EXPECT_THAT(hairpipe::Renderer::create(*context, s).message(),
              HasSubstr("RendererSettings.velocityOutput.attachment must be -1 (none) or an index into "
                        "formats.otherColors (1 of them), got 1"));
  s.velocityOutput.attachment = 0;
  const hairpipe::Result<hairpipe::Renderer> renderer = hairpipe::Renderer::create(*context, s);
  EXPECT_TRUE(renderer.ok()) << renderer.message();
  s.raster = hairpipe::RasterMode::Graphics;
  EXPECT_THAT(hairpipe::Renderer::create(*context, s).message(), HasSubstr("motionVectors needs the compute raster"));
  hairpipe::test::expectIdleAndSilent(*context);
}
}  // namespace
