// Motion vectors and jitter (RendererSettings::motionVectors, View::jitter, View::previousViewProj) on the
// compute rasterizer: a head turned rigidly about the camera's eye moves every hair pixel as the analytic
// rotation does (depth-independent); a camera whose previous view-projection was shifted in clip space
// gives every hair pixel that shift; still hair has no motion; a subpixel jitter moves the hair's coverage
// by the jitter and leaves the motion alone.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <iostream>
#include <vector>

#include "compute/renderer/renderer.h"
#include "engine/core/error.h"
#include "engine/vk/submit.h"
#include "samples/tools/offscreen_renderer.h"
#include "tests/support/small_frame.h"
#include "tests/support/vk_fixture.h"

using hp::test::VulkanTest;

namespace {
using hp::test::kSmallHeight;
using hp::test::kSmallWidth;

struct MotionFrame {
  std::vector<glm::vec2> motion;
  std::vector<float> coverage;
};

// One head with motion vectors on, settled still for a few frames (no gravity: it rests where it grew).
class MotionScene {
 public:
  explicit MotionScene(const hp::vk::Context& ctx)
      : ctx_(ctx), target_(ctx, kSmallWidth, kSmallHeight, 1, hp::RasterMode::Compute) {
    hp::RendererSettings settings;
    settings.formats = target_.formats();
    settings.raster = hp::RasterMode::Compute;
    settings.opacity.resolution = 128;
    settings.motionVectors = true;
    renderer_ = std::make_unique<hp::Renderer>(ctx, settings);
    hp::InstanceSettings instance;
    instance.simulation.gravity = glm::dvec3(0.0);
    instance_ = renderer_->createInstance(hp::test::defaultHeadWithStrands(3000), instance);
    hp::HairInstance* const list[] = {instance_.get()};
    target_.attach(*renderer_, list);
    for (int i = 0; i < 6; ++i) render(hp::test::smallFrontView());
  }

  MotionFrame render(const hp::View& view) {
    hp::HairInstance* const list[] = {instance_.get()};
    hp::vk::submitAndWait(ctx_, [&](VkCommandBuffer cmd) {
      renderer_->recordUpdate(cmd, frame_, list);
      renderer_->recordShadows(cmd, frame_, hp::LightSpec{}, list);
      target_.record(cmd, *renderer_, frame_, view, list, 1.0f);
    }, "motion frame");
    ++frame_;
    return {renderer_->rasterMotion(), renderer_->rasterCoverage()};
  }

  hp::HairInstance& instance() { return *instance_; }
  hp::Renderer& renderer() { return *renderer_; }

 private:
  const hp::vk::Context& ctx_;
  hp::render::OffscreenRenderer target_;
  std::unique_ptr<hp::Renderer> renderer_;
  std::unique_ptr<hp::HairInstance> instance_;
  std::uint64_t frame_ = 0;
};

// Mean |motion - expected(pixel)| over the pixels the hair covers by more than a quarter.
template <typename Expected>
double meanError(const MotionFrame& f, Expected expected, std::size_t& pixels) {
  double sum = 0.0;
  pixels = 0;
  for (std::uint32_t y = 0; y < kSmallHeight; ++y)
    for (std::uint32_t x = 0; x < kSmallWidth; ++x) {
      const std::size_t i = std::size_t(y) * kSmallWidth + x;
      if (f.coverage[i] <= 0.25f) continue;
      sum += glm::length(f.motion[i] - expected(glm::vec2(x + 0.5f, y + 0.5f)));
      ++pixels;
    }
  return pixels ? sum / double(pixels) : 1e9;
}

glm::vec2 pixelOf(const glm::mat4& viewProj, const glm::vec3& world) {
  const glm::vec4 clip = viewProj * glm::vec4(world, 1.0f);
  const glm::vec2 ndc = glm::vec2(clip) / clip.w;
  return {(ndc.x * 0.5f + 0.5f) * kSmallWidth, (0.5f - ndc.y * 0.5f) * kSmallHeight};
}

// A world point seen at `pixel` (on the ray through it, at view depth 1).
glm::vec3 worldAt(const hp::CameraMatrices& camera, glm::vec2 pixel) {
  const glm::vec2 ndc(pixel.x / kSmallWidth * 2.0f - 1.0f, 1.0f - pixel.y / kSmallHeight * 2.0f);
  const glm::mat4 inverse = glm::inverse(camera.proj * camera.view);
  const glm::vec4 nearPoint = inverse * glm::vec4(ndc, 0.5f, 1.0f);
  const glm::vec3 p = glm::vec3(nearPoint) / nearPoint.w;
  return camera.position + glm::normalize(p - camera.position);
}
}  // namespace

// The head turns by 3 degrees about the vertical axis through the camera's eye (carried rigidly: teleport):
// each hair point moves like the camera turning the other way, so every pixel's motion is known without its
// depth. Mean error over the covered pixels: under 0.25 pixels.
TEST_F(VulkanTest, MotionVectorsOfARigidlyTurnedHeadMatchTheAnalyticScreenMotion) {
  MotionScene scene(*ctx);
  const hp::View view = hp::test::smallFrontView();
  const glm::vec3 eye = view.camera.position;
  const glm::mat4 turn = glm::translate(glm::mat4(1.0f), eye) *
                         glm::rotate(glm::mat4(1.0f), glm::radians(3.0f), glm::vec3(0.0f, 1.0f, 0.0f)) *
                         glm::translate(glm::mat4(1.0f), -eye);
  const MotionFrame still = scene.render(view);
  scene.instance().setMotion({glm::mat4(1.0f), turn, 0.1, true});
  const MotionFrame turned = scene.render(view);
  const glm::mat4 viewProj = view.camera.proj * view.camera.view;
  std::size_t stillPixels = 0, turnedPixels = 0;
  const double stillError = meanError(still, [](glm::vec2) { return glm::vec2(0.0f); }, stillPixels);
  double analyticMean = 0.0;
  const double turnedError = meanError(turned, [&](glm::vec2 pixel) {
    // The point now at `pixel` was at turn^-1 of it.
    const glm::vec3 now = worldAt(view.camera, pixel);
    const glm::vec2 motion = pixel - pixelOf(viewProj, glm::vec3(glm::inverse(turn) * glm::vec4(now, 1.0f)));
    analyticMean += glm::length(motion);
    return motion;
  }, turnedPixels);
  analyticMean /= double(std::max<std::size_t>(turnedPixels, 1));
  std::cout << "still hair: mean |motion| " << stillError << " px over " << stillPixels
            << " pixels; turned 3 degrees: analytic motion " << analyticMean << " px, mean error " << turnedError
            << " px over " << turnedPixels << " pixels\n";
  EXPECT_GT(stillPixels, std::size_t(kSmallWidth * kSmallHeight / 20));  // enough pixels to judge
  EXPECT_LT(stillError, 0.05);
  EXPECT_GT(analyticMean, 5.0);
  EXPECT_LT(turnedError, 0.25);
}

// The camera's motion comes from View::previousViewProj: a previous view-projection shifted by (+3, -2)
// pixels makes every still hair pixel move by (-3, +2).
TEST_F(VulkanTest, MotionVectorsFollowThePreviousViewProjection) {
  MotionScene scene(*ctx);
  hp::View view = hp::test::smallFrontView();
  glm::mat4 shift(1.0f);
  shift[3][0] = 2.0f * 3.0f / kSmallWidth;
  shift[3][1] = -2.0f * -2.0f / kSmallHeight;
  view.previousViewProj = shift * view.camera.proj * view.camera.view;
  std::size_t pixels = 0;
  const double error = meanError(scene.render(view), [](glm::vec2) { return glm::vec2(-3.0f, 2.0f); }, pixels);
  std::cout << "previous camera shifted (3, -2) px: mean error " << error << " px over " << pixels << " pixels\n";
  EXPECT_LT(error, 0.05);
}

// A jitter of (0.5, -0.25) pixels moves the hair's coverage centroid by it and leaves still hair without
// motion. From far enough that the whole head is in the frame (no hair enters at an edge).
TEST_F(VulkanTest, JitterMovesTheHairBySubpixelsAndNotItsMotion) {
  MotionScene scene(*ctx);
  hp::View view = hp::test::smallFrontView(1.6f);
  const auto centroid = [](const std::vector<float>& coverage) {
    glm::dvec2 sum(0.0);
    double total = 0.0;
    for (std::uint32_t y = 0; y < kSmallHeight; ++y)
      for (std::uint32_t x = 0; x < kSmallWidth; ++x) {
        const double c = coverage[std::size_t(y) * kSmallWidth + x];
        sum += c * glm::dvec2(x + 0.5, y + 0.5);
        total += c;
      }
    return sum / total;
  };
  const MotionFrame plain = scene.render(view);
  view.jitter = {0.5f, -0.25f};
  const MotionFrame jittered = scene.render(view);
  const glm::dvec2 moved = centroid(jittered.coverage) - centroid(plain.coverage);
  std::size_t pixels = 0;
  const double still = meanError(jittered, [](glm::vec2) { return glm::vec2(0.0f); }, pixels);
  std::cout << "jitter (0.5, -0.25): the coverage centroid moved (" << moved.x << ", " << moved.y
            << "), mean |motion| " << still << " px\n";
  EXPECT_NEAR(moved.x, 0.5, 0.05);
  EXPECT_NEAR(moved.y, -0.25, 0.05);
  EXPECT_LT(still, 0.05);
  view.jitter = {1.5f, 0.0f};
  EXPECT_THROW(scene.render(view), hp::Error);
}

TEST_F(VulkanTest, MotionVectorsAreRefusedWhenTheRendererWasMadeWithout) {
  hp::render::OffscreenRenderer target(*ctx, kSmallWidth, kSmallHeight, 1, hp::RasterMode::Compute);
  hp::RendererSettings settings;
  settings.formats = target.formats();
  settings.raster = hp::RasterMode::Compute;
  hp::Renderer renderer(*ctx, settings);
  try {
    renderer.motionImage();
    FAIL() << "motionImage() without motion vectors";
  } catch (const hp::Error& e) {
    EXPECT_NE(std::string(e.what()).find("motionVectors"), std::string::npos) << e.what();
  }
}
