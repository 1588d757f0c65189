// Hair stays off the face: the default head, settled and seen from the front, with its render
// strands read back and drawn on the CPU as one-pixel lines against the face region of the head's
// field (pixels whose first surface hit, by sphere tracing the field, is on the face). Hair in front
// of the face may cover less than 5% of it.
#include <gtest/gtest.h>

#include <iostream>

#include "engine/core/hair/head_sdf.h"
#include "compute/raster/camera.h"
#include "samples/tools/render_job.h"
#include "tests/support/vk_fixture.h"

using namespace hp;
using hp::test::VulkanTest;

namespace {
constexpr std::uint32_t kFaceWidth = 160, kFaceHeight = 120;

struct FacePixels {
  std::vector<float> depth;  // distance to the face along the pixel's ray; < 0: not face
  std::size_t count = 0;
};

glm::vec3 pixelRay(const CameraMatrices& cam, float px, float py) {
  const glm::mat4 inv = glm::inverse(cam.proj * cam.view);
  const glm::vec2 ndc(2.0f * px / kFaceWidth - 1.0f, 2.0f * py / kFaceHeight - 1.0f);
  const glm::vec4 far = inv * glm::vec4(ndc, 1.0f, 1.0f);
  return glm::normalize(glm::vec3(far) / far.w - cam.position);
}

FacePixels facePixels(const CameraMatrices& cam) {
  FacePixels f;
  f.depth.assign(std::size_t(kFaceWidth) * kFaceHeight, -1.0f);
  for (std::uint32_t y = 0; y < kFaceHeight; ++y)
    for (std::uint32_t x = 0; x < kFaceWidth; ++x) {
      const glm::vec3 dir = pixelRay(cam, x + 0.5f, y + 0.5f);
      float t = 0.0f;
      for (int step = 0; step < 256 && t < 3.0f; ++step) {
        const float d = headDistance(cam.position + t * dir);
        if (d < 1e-4f) {
          if (inFaceRegion(cam.position + t * dir)) f.depth[std::size_t(y) * kFaceWidth + x] = t, ++f.count;
          break;
        }
        t += d;
      }
    }
  return f;
}
}  // namespace

TEST_F(VulkanTest, SettledDefaultHairCoversUnderFivePercentOfTheFaceFromTheFront) {
  RenderRequest r;
  r.scene.render = {kFaceWidth, kFaceHeight, 1};
  r.scene.camera.orbitDeg = 0.0f;
  r.settleFrames = 60;
  r.opacity.enabled = false;
  r.captureStrands = true;
  const RenderResult result = renderStill(*ctx, buildSceneAsset(r.scene), r);
  ASSERT_TRUE(result.strandDump);
  const CameraMatrices cam = orbitCamera(r.scene.camera, float(kFaceWidth) / float(kFaceHeight));
  const FacePixels face = facePixels(cam);
  ASSERT_GT(face.count, 400u) << "the face should fill a good part of the frame";
  std::vector<bool> covered(face.depth.size(), false);
  const auto& pts = result.strandDump->points;
  const auto offsets = result.strandDump->strandOffsets();
  for (std::uint32_t s = 0; s < result.strandDump->strandCount; ++s)
    for (std::uint32_t i = offsets[s]; i + 1 < offsets[s + 1]; ++i)
      for (int k = 0; k < 8; ++k) {  // Q = 36 points per strand: 8 samples per segment is sub-pixel here
        const glm::vec3 p = glm::mix(pts[i], pts[i + 1], (k + 0.5f) / 8.0f);
        const glm::vec4 clip = cam.proj * cam.view * glm::vec4(p, 1.0f);
        if (clip.w <= 0.0f) continue;
        const float px = (clip.x / clip.w * 0.5f + 0.5f) * kFaceWidth, py = (clip.y / clip.w * 0.5f + 0.5f) * kFaceHeight;
        if (px < 0.0f || py < 0.0f || px >= kFaceWidth || py >= kFaceHeight) continue;
        const std::size_t pixel = std::size_t(py) * kFaceWidth + std::size_t(px);
        if (face.depth[pixel] > 0.0f && glm::length(p - cam.position) < face.depth[pixel] - 1e-3f) covered[pixel] = true;
      }
  std::size_t hits = 0;
  for (bool c : covered) hits += c;
  const double fraction = double(hits) / double(face.count);
  std::cout << "hair covers " << 100.0 * fraction << " % of " << face.count << " face pixels\n";
  EXPECT_LT(fraction, 0.05);
}
