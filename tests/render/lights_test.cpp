// Several lights per frame (Renderer::recordShadows with a list): the frame lit by three shadowed lights is
// the sum of the three frames lit by each alone; each light's own shadows darken the hair on its far side;
// a second shadowed light's maps hold every instance (one head shadows another); lights past the Renderer's
// shadow slots shade unshadowed; bad lists are refused before anything is recorded. Both rasterizers.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <iostream>
#include <vector>

#include "compute/renderer/renderer.h"
#include "compute/shadows/frame_lights.h"
#include "engine/core/error.h"
#include "engine/vk/submit.h"
#include "samples/tools/offscreen_renderer.h"
#include "tests/support/small_frame.h"
#include "tests/support/vk_fixture.h"

using hp::test::VulkanTest;

namespace {
using hp::test::kSmallHeight;
using hp::test::kSmallWidth;

// A key from the upper right, a spot from the left and a point light above and behind: three kinds, three
// colours, each on its own side of the head.
std::vector<hp::LightSpec> threeLights() {
  hp::LightSpec key;
  key.direction = glm::normalize(glm::vec3(0.8f, 0.4f, 0.45f));
  key.color = {1.0f, 0.9f, 0.8f};
  key.intensity = 2.5f;
  hp::LightSpec fill = hp::LightSpec::makeSpot({-0.6f, 0.1f, 0.35f}, {0.0f, -0.02f, 0.0f}, 40.0f);
  fill.color = {0.6f, 0.7f, 1.0f};
  fill.intensity = 1.5f;
  hp::LightSpec rim = hp::LightSpec::makePoint({0.0f, 0.45f, -0.45f}, 0.6f);
  rim.color = {1.0f, 0.95f, 0.7f};
  rim.intensity = 3.0f;
  return {key, fill, rim};
}

// One Renderer with instances of the default head, rendered at the small frame without stepping the
// simulation after the first frame, so frames differ only by their lights (and instance sets).
class LitScene {
 public:
  LitScene(const hp::vk::Context& ctx, hp::RasterMode raster, std::uint32_t shadowedLights,
           const std::vector<glm::mat4>& heads, std::uint32_t strands = 1500)
      : ctx_(ctx), raster_(raster), target_(ctx, kSmallWidth, kSmallHeight, 1, raster) {
    hp::RendererSettings settings;
    settings.formats = target_.formats();
    settings.raster = raster;
    settings.opacity.resolution = 256;
    settings.shadowedLights = shadowedLights;
    renderer_ = std::make_unique<hp::Renderer>(ctx, settings);
    hp::InstanceSettings instance;
    instance.look.ambient = 0.0f;        // the ambient would count once per frame of a sum
    instance.look.skinBounce = false;    // the bounce follows slot 0's light only
    const hp::HairAsset asset = hp::test::defaultHeadWithStrands(strands);
    for (const glm::mat4& head : heads) instances_.push_back(renderer_->createInstance(asset, instance, head));
  }

  hp::LinearImage render(const std::vector<hp::LightSpec>& lights, const hp::View& view,
                                 std::vector<std::size_t> which = {}) {
    if (which.empty())
      for (std::size_t i = 0; i < instances_.size(); ++i) which.push_back(i);
    std::vector<hp::HairInstance*> list;
    for (std::size_t i : which) list.push_back(instances_[i].get());
    const std::span<hp::HairInstance* const> span(list);
    if (raster_ == hp::RasterMode::Compute) target_.attach(*renderer_, span);
    hp::vk::submitAndWait(ctx_, [&](VkCommandBuffer cmd) {
      if (frame_ == 0) renderer_->recordUpdate(cmd, frame_, span);
      renderer_->recordShadows(cmd, frame_, lights, span);
      if (raster_ == hp::RasterMode::Compute)
        target_.record(cmd, *renderer_, frame_, view, span, 1.0f);
      else
        target_.record(cmd, [&](VkCommandBuffer c) { renderer_->recordDraw(c, frame_, view, span); }, 1.0f);
    }, "lit scene");
    ++frame_;
    return target_.readLinear();
  }

  hp::Renderer& renderer() { return *renderer_; }
  std::vector<hp::HairInstance*> all() const {
    std::vector<hp::HairInstance*> list;
    for (const auto& i : instances_) list.push_back(i.get());
    return list;
  }

 private:
  const hp::vk::Context& ctx_;
  hp::RasterMode raster_;
  hp::render::OffscreenRenderer target_;
  std::unique_ptr<hp::Renderer> renderer_;
  std::vector<std::unique_ptr<hp::HairInstance>> instances_;
  std::uint64_t frame_ = 0;
};

float luminance(const hp::LinearImage& image, std::uint32_t x, std::uint32_t y) {
  return 0.2126f * image.at(x, y, 0) + 0.7152f * image.at(x, y, 1) + 0.0722f * image.at(x, y, 2);
}

float meanLuminance(const hp::LinearImage& image, std::uint32_t x0, std::uint32_t x1) {
  double sum = 0.0;
  for (std::uint32_t y = 0; y < image.height; ++y)
    for (std::uint32_t x = x0; x < x1; ++x) sum += luminance(image, x, y);
  return float(sum / (double(image.height) * (x1 - x0)));
}

void expectLightsAddUp(const hp::vk::Context& ctx, hp::RasterMode raster, const char* path) {
  LitScene scene(ctx, raster, 3, {glm::mat4(1.0f)});
  const hp::View view = hp::test::smallFrontView();
  const std::vector<hp::LightSpec> lights = threeLights();
  const hp::LinearImage background = scene.render({}, view);  // no light: black hair over the clear
  const hp::LinearImage all = scene.render(lights, view);
  std::vector<hp::LinearImage> alone;
  for (const hp::LightSpec& l : lights) alone.push_back(scene.render({l}, view));
  // all - background = sum over lights of (alone - background), channel by channel.
  double error = 0.0, signal = 0.0;
  std::size_t off = 0;
  for (std::size_t v = 0; v < all.values.size(); ++v) {
    double sum = 0.0;
    for (const auto& a : alone) sum += a.values[v] - background.values[v];
    const double lit = all.values[v] - background.values[v];
    error += std::abs(lit - sum);
    signal += std::abs(lit);
    off += std::abs(lit - sum) > 0.02 * std::abs(lit) + 1e-3;
  }
  std::cout << path << ": three lights against the sum of each alone: mean |error| " << error / signal
            << " of the mean signal; values off by > 2%: " << off << " of " << all.values.size() << "\n";
  ASSERT_GT(signal / double(all.values.size()), 0.01) << path << ": the lights lit nothing";
  // The shading is linear in each light; what differs is the compute raster's order of equal-depth fragments
  // and float rounding.
  EXPECT_LT(error / signal, 0.005) << path;
  EXPECT_LT(off, all.values.size() / 500) << path;
}

// Each light with its shadows on, against the same light list with that light's shadows off: the darkening
// lies on the side of the head away from the light (the image's right half for a light from the left).
void expectEachLightShadowsItsFarSide(const hp::vk::Context& ctx, hp::RasterMode raster, const char* path) {
  LitScene scene(ctx, raster, 2, {glm::mat4(1.0f)});
  const hp::View view = hp::test::smallFrontView();
  hp::LightSpec fromLeft, fromRight;
  fromLeft.direction = glm::normalize(glm::vec3(-1.0f, 0.15f, 0.1f));
  fromRight.direction = glm::normalize(glm::vec3(1.0f, 0.15f, 0.1f));
  const std::vector<hp::LightSpec> both = {fromLeft, fromRight};
  const hp::LinearImage shadowed = scene.render(both, view);
  const std::uint32_t half = kSmallWidth / 2;
  for (int which = 0; which < 2; ++which) {
    std::vector<hp::LightSpec> unshadowed = both;
    unshadowed[which].shadows = false;
    const hp::LinearImage open = scene.render(unshadowed, view);
    const float leftDrop = meanLuminance(open, 0, half) - meanLuminance(shadowed, 0, half);
    const float rightDrop = meanLuminance(open, half, kSmallWidth) - meanLuminance(shadowed, half, kSmallWidth);
    std::cout << path << ": light from the " << (which == 0 ? "left" : "right")
              << ": its shadows darken the left half by " << leftDrop << ", the right half by " << rightDrop << "\n";
    const float farDrop = which == 0 ? rightDrop : leftDrop, nearDrop = which == 0 ? leftDrop : rightDrop;
    EXPECT_GT(farDrop, 0.0f) << path;
    EXPECT_GT(farDrop, 1.5f * nearDrop) << path << ": the shadows should fall on the far side";
  }
}
}  // namespace

TEST_F(VulkanTest, ThreeLightsAddUpToEachAloneCompute) {
  expectLightsAddUp(*ctx, hp::RasterMode::Compute, "compute");
}
TEST_F(VulkanTest, ThreeLightsAddUpToEachAloneGraphics) {
  expectLightsAddUp(*ctx, hp::RasterMode::Graphics, "graphics");
}

TEST_F(VulkanTest, EachShadowedLightDarkensTheHairOnItsFarSideCompute) {
  expectEachLightShadowsItsFarSide(*ctx, hp::RasterMode::Compute, "compute");
}
TEST_F(VulkanTest, EachShadowedLightDarkensTheHairOnItsFarSideGraphics) {
  expectEachLightShadowsItsFarSide(*ctx, hp::RasterMode::Graphics, "graphics");
}

// Two heads side by side, the second light (slot 1) from the left through the left head onto the right one:
// the right head is darker with its neighbour there (the slot's maps hold both instances).
TEST_F(VulkanTest, ASecondShadowedLightsMapsHoldEveryInstance) {
  const glm::mat4 left = glm::translate(glm::mat4(1.0f), {-0.16f, 0.0f, 0.0f});
  const glm::mat4 right = glm::translate(glm::mat4(1.0f), {0.16f, 0.0f, 0.0f});
  LitScene scene(*ctx, hp::RasterMode::Compute, 2, {left, right}, 800);
  const hp::View view = hp::test::smallFrontView(1.3f);
  hp::LightSpec front;  // slot 0, dark: the frame shows slot 1's light only
  front.direction = glm::normalize(glm::vec3(0.0f, 0.3f, 1.0f));
  front.intensity = 0.0f;
  hp::LightSpec side;  // slot 1: from the left, nearly horizontal
  side.direction = glm::normalize(glm::vec3(-1.0f, 0.05f, 0.05f));
  const std::vector<hp::LightSpec> lights = {front, side};
  const hp::LinearImage both = scene.render(lights, view, {0, 1});
  const hp::LinearImage alone = scene.render(lights, view, {1});
  const std::uint32_t x0 = kSmallWidth / 2 + 8;  // the right head's half, clear of the left head
  const float withNeighbour = meanLuminance(both, x0, kSmallWidth), withoutIt = meanLuminance(alone, x0, kSmallWidth);
  std::cout << "right head's half: " << withNeighbour << " with the left head in slot 1's light, " << withoutIt
            << " alone\n";
  // Were the left head missing from slot 1's maps, the right head would be as bright as alone (ratio 1).
  EXPECT_GT(withoutIt, 0.005f);
  EXPECT_LT(withNeighbour, 0.9f * withoutIt);
}

// A crowd: 32 heads in a 8 x 4 grid under three shadowed lights (each light's maps over all of them),
// rendered by the compute rasterizer under sync validation (the fixture fails on any message).
TEST_F(VulkanTest, ThirtyTwoInstancesRenderUnderThreeShadowedLights) {
  std::vector<glm::mat4> heads;
  for (int row = 0; row < 4; ++row)
    for (int column = 0; column < 8; ++column)
      heads.push_back(glm::translate(glm::mat4(1.0f), {0.35f * (column - 3.5f), 0.0f, -0.45f * row}));
  LitScene scene(*ctx, hp::RasterMode::Compute, 3, heads, 150);
  const hp::View view = hp::test::smallFrontView(3.2f);
  const hp::LinearImage image = scene.render(threeLights(), view);
  EXPECT_GT(meanLuminance(image, 0, kSmallWidth), 0.005f);
}

// Past the Renderer's shadow slots a light shades unshadowed: three shadowed lights on one slot render as
// the list whose last two lights ask for no shadows.
TEST_F(VulkanTest, LightsPastTheShadowSlotsShadeUnshadowed) {
  LitScene scene(*ctx, hp::RasterMode::Compute, 1, {glm::mat4(1.0f)});
  const hp::View view = hp::test::smallFrontView();
  std::vector<hp::LightSpec> lights = threeLights();
  const hp::LinearImage oneSlot = scene.render(lights, view);
  lights[1].shadows = lights[2].shadows = false;
  const hp::LinearImage asked = scene.render(lights, view);
  double diff = 0.0, signal = 0.0;
  for (std::size_t v = 0; v < asked.values.size(); ++v) {
    diff += std::abs(oneSlot.values[v] - asked.values[v]);
    signal += std::abs(asked.values[v]);
  }
  EXPECT_LT(diff / signal, 0.002);
  const hp::render::FrameLights f = hp::render::assignShadowSlots(threeLights(), 1);
  EXPECT_EQ(f.slots, (std::vector<int>{0, -1, -1}));
}

TEST_F(VulkanTest, BadLightListsAreRefusedBeforeRecording) {
  LitScene scene(*ctx, hp::RasterMode::Graphics, 2, {glm::mat4(1.0f)}, 200);
  std::vector<hp::HairInstance*> list = scene.all();
  const std::span<hp::HairInstance* const> span(list);
  std::vector<hp::LightSpec> nine(9);
  std::vector<hp::LightSpec> bad = threeLights();
  bad[2].intensity = NAN;
  const auto refusal = [&](const std::vector<hp::LightSpec>& lights) {
    std::string message;
    hp::vk::submitAndWait(*ctx, [&](VkCommandBuffer cmd) {
      try {
        scene.renderer().recordShadows(cmd, 0, lights, span);
      } catch (const hp::Error& e) {
        message = e.what();
      }
    }, "refused lights");
    return message;
  };
  EXPECT_NE(refusal(nine).find("at most 8 lights"), std::string::npos) << refusal(nine);
  EXPECT_NE(refusal(bad).find("intensity"), std::string::npos) << refusal(bad);
}

TEST(FrameLights, ShadowSlotsGoToTheFirstLightsThatAskInOrder) {
  std::vector<hp::LightSpec> lights(6);
  lights[1].shadows = false;
  const hp::render::FrameLights f = hp::render::assignShadowSlots(lights, 4);
  EXPECT_EQ(f.slots, (std::vector<int>{0, -1, 1, 2, 3, -1}));
  EXPECT_EQ(f.shadowed(), 4u);
  EXPECT_EQ(f.lightOfSlot(2), 3);
  EXPECT_EQ(f.lightOfSlot(4), -1);
  EXPECT_EQ(hp::render::assignShadowSlots({}, 4).shadowed(), 0u);
}

TEST(FrameLights, APointLightsShadowsAreASpotAimedAtTheHeads) {
  const hp::render::HeadSphere heads{{0.0f, 0.1f, 0.0f}, 0.12f};
  const hp::LightSpec point = hp::LightSpec::makePoint({0.0f, 0.1f, 1.0f}, 0.5f);
  const hp::LightSpec spot = hp::render::shadowFrustum(point, heads);
  EXPECT_EQ(spot.type, hp::LightSpec::Type::Spot);
  EXPECT_NEAR(glm::length(spot.direction - glm::vec3(0.0f, 0.0f, 1.0f)), 0.0f, 1e-6f);  // toward the light
  EXPECT_EQ(spot.position, point.position);
  EXPECT_NO_THROW(spot.validate());
}
