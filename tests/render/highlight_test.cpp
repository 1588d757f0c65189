// Marschner's predictions, checked in rendered images (semantic checks that survive driver changes):
// a sheet of straight-combed hair draped over a cylinder, seen from behind and above like hair on a
// head. Moving the light moves the highlight band, and the R and TRT highlights sit where the model
// puts them: R where theta_h = alpha_R, TRT where theta_h = -3 alpha_R / 2.
// Note on "toward the root": alpha_R < 0 shifts the R *lobe* toward the root in direction space.
// On hair seen from outside a convex (or flat) surface theta_h falls from root to tip (the tangent
// turns away from eye and light), so in the *image* the white R band sits tipward of the coloured
// TRT band -- the classic observation behind two-highlight real-time hair shaders.
#include <gtest/gtest.h>

#include <iostream>

#include <cmath>

#include "compute/raster/camera.h"
#include "samples/tools/render_job.h"
#include "tests/support/vk_fixture.h"

using namespace hp;
using hp::test::VulkanTest;

namespace {
constexpr float kRadius = 0.1f;
constexpr std::uint32_t kGuides = 48, kParticles = 7;

// Guides start on the top of a cylinder along X and run back and down over it (psi from 0 to 110 deg).
HairAsset arcSheet() {
  HairAsset asset;
  asset.name = "arc sheet";
  asset.guides.particlesPerGuide = kParticles;
  for (std::uint32_t g = 0; g < kGuides; ++g) {
    const float x = -0.06f + 0.12f * float(g) / float(kGuides - 1);
    for (std::uint32_t i = 0; i < kParticles; ++i) {
      const float psi = glm::radians(110.0f) * float(i) / float(kParticles - 1);
      asset.guides.positions.emplace_back(x, kRadius * std::cos(psi), -kRadius * std::sin(psi));
    }
  }
  return asset;
}

RenderRequest sheetRequest(float lightElevationDeg, LutMode mode = LutMode::Float) {
  RenderRequest r;
  r.lutMode = mode;
  r.scene.render = {160, 160, 4};
  r.scene.camera.orbitDeg = 180.0f;  // behind the "head"
  r.scene.camera.elevationDeg = 25.0f;
  r.scene.camera.distance = 0.45f;
  r.scene.camera.target = {0.0f, 0.02f, -0.05f};
  const float e = glm::radians(lightElevationDeg);
  r.scene.lights[0].direction = glm::normalize(glm::vec3(0.0f, std::sin(e), -std::cos(e)));  // from the camera's side
  r.scene.lights[0].intensity = 4.0f;
  r.scene.material.absorption = {0.15, 0.35, 0.9};  // blonde: TRT is clearly yellow, R stays white
  r.scene.simulation.gravity = {0.0, 0.0, 0.0};
  r.scene.simulation.stiffness = 1.0;  // hold the rest pose exactly
  r.settleFrames = 0;
  r.guidesOnly = true;
  r.look.strandWidth = 0.004f;
  r.look.ambient = 0.0f;
  return r;
}

// Rows (top to bottom) of the central columns: blue (R is white, TRT has little blue in blonde hair)
// and red minus blue (only the coloured lobes; R adds equally to both).
struct RowProfile {
  std::vector<double> blue, warm;
  int peak(const std::vector<double>& v) const { return int(std::max_element(v.begin(), v.end()) - v.begin()); }
};

RowProfile profile(const RenderResult& img) {
  RowProfile p;
  for (std::uint32_t y = 0; y < img.height; ++y) {
    double b = 0, w = 0;
    for (std::uint32_t x = img.width * 2 / 5; x < img.width * 3 / 5; ++x) {
      const std::uint8_t* px = &img.rgba[4 * (std::size_t(y) * img.width + x)];
      b += px[2];
      w += double(px[0]) - double(px[2]);
    }
    p.blue.push_back(b);
    p.warm.push_back(w);
  }
  return p;
}
}  // namespace

TEST_F(VulkanTest, MovingTheLightMovesTheHighlightBand) {
  const HairAsset asset = arcSheet();
  RowProfile low = profile(renderStill(*ctx, asset, sheetRequest(10.0f)));
  RowProfile high = profile(renderStill(*ctx, asset, sheetRequest(60.0f)));
  const int lowRow = low.peak(low.blue), highRow = high.peak(high.blue);
  // A light higher above the sheet moves the mirror point up the arc, toward the roots (image top).
  EXPECT_LT(highRow, lowRow - 4) << "highlight row with the light at 60 deg: " << highRow << ", at 10 deg: " << lowRow;
  EXPECT_GT(*std::max_element(low.blue.begin(), low.blue.end()), 0.0);
}

namespace {
// The image row where the sheet's centre strand has theta_h = target (degrees), by bisection on psi.
double predictedRow(const RenderRequest& r, double targetDeg) {
  const CameraMatrices cam = orbitCamera(r.scene.camera, 1.0f);
  const glm::dvec3 L = glm::normalize(glm::dvec3(r.scene.lights[0].direction));
  auto thetaH = [&](double psi) {
    glm::dvec3 p(0.0, kRadius * std::cos(psi), -kRadius * std::sin(psi));
    glm::dvec3 t(0.0, -std::sin(psi), -std::cos(psi));
    glm::dvec3 v = glm::normalize(glm::dvec3(cam.position) - p);
    return glm::degrees(0.5 * (std::asin(glm::dot(L, t)) + std::asin(glm::dot(v, t))));
  };
  double lo = 0.0, hi = glm::radians(110.0);  // theta_h decreases along the arc
  for (int i = 0; i < 60; ++i) {
    double mid = 0.5 * (lo + hi);
    (thetaH(mid) > targetDeg ? lo : hi) = mid;
  }
  glm::vec4 clip = cam.proj * cam.view * glm::vec4(0.0f, kRadius * std::cos(lo), -kRadius * std::sin(lo), 1.0f);
  return (1.0 - (clip.y / clip.w * 0.5 + 0.5)) * r.scene.render.height;  // row 0 is the top
}
}  // namespace

// The paper's model (float LUTs): TRT at theta_h = -3 alpha_R / 2.
TEST_F(VulkanTest, PrimaryAndSecondaryHighlightsSitWhereTheLobeShiftsPutThem) {
  const RenderRequest request = sheetRequest(35.0f);
  RowProfile p = profile(renderStill(*ctx, arcSheet(), request));
  const int rRow = p.peak(p.blue), trtRow = p.peak(p.warm);
  const double alphaR = glm::degrees(request.scene.material.alphaR);
  const double rPredicted = predictedRow(request, alphaR), trtPredicted = predictedRow(request, -1.5 * alphaR);
  EXPECT_NEAR(rRow, rPredicted, 6.0) << "R (white) peak row";
  EXPECT_NEAR(trtRow, trtPredicted, 8.0) << "TRT (coloured) peak row";
  // Roots are at the top of the image: the white band lies tipward (below) of the coloured one.
  EXPECT_GT(rRow, trtRow + 5) << "R row " << rRow << ", TRT row " << trtRow;
}

// The physical model: R at theta_h = alpha_R as in the paper, TRT tilted by -4 alpha_R (pbrt-v3's
// magnitude), i.e. at theta_h = -2 alpha_R. Same tolerances as the paper model's test.
TEST_F(VulkanTest, PhysicalModelHighlightsSitWhereItsTiltsPutThem) {
  const RenderRequest request = sheetRequest(35.0f, LutMode::Physical);
  RowProfile p = profile(renderStill(*ctx, arcSheet(), request));
  const int rRow = p.peak(p.blue), trtRow = p.peak(p.warm);
  const double alphaR = glm::degrees(request.scene.material.alphaR);
  const double rPredicted = predictedRow(request, alphaR), trtPredicted = predictedRow(request, -2.0 * alphaR);
  std::cout << "physical: R row " << rRow << " (predicted " << rPredicted << "), TRT row " << trtRow << " (predicted "
            << trtPredicted << ")\n";
  EXPECT_NEAR(rRow, rPredicted, 6.0) << "R (white) peak row";
  EXPECT_NEAR(trtRow, trtPredicted, 8.0) << "TRT (coloured) peak row";
  EXPECT_GT(rRow, trtRow + 5) << "R row " << rRow << ", TRT row " << trtRow;
}
