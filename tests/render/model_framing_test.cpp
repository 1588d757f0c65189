// Real models out of the box: synthetic .hair heads in millimetres, centimetres and metres, Y or Z up,
// get their units and up axis guessed and a camera framed on them, and render with hair covering
// 5-80% of the frame without a scene.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "engine/core/error.h"
#include "samples/tools/host/camera_fit.h"
#include "engine/core/hair/hair_file.h"
#include "engine/core/hair/hair_import.h"
#include "samples/tools/host/model_guess.h"
#include "samples/tools/render_job.h"
#include "engine/core/hair/scene.h"
#include "tests/hair/gltf_test_file.h"
#include "tests/hair/hair_test_util.h"
#include "tests/support/vk_fixture.h"

using namespace hp;
using hp::test::VulkanTest;

namespace {
constexpr std::uint32_t kFramingWidth = 160, kFramingHeight = 120;

// A still of the hair as imported (no settling) on the compute raster, its hair coverage read back.
RenderRequest coverageRequest() {
  RenderRequest r;
  r.scene.render = {kFramingWidth, kFramingHeight, 1};
  r.scene.render.raster = RasterMode::Compute;
  r.settleFrames = 0;
  r.captureFrame = true;
  return r;
}

// The share of the frame the hair covers (its exported alpha, summed).
double hairAlphaCoverage(const RenderResult& result) {
  if (!result.frame) throw Error("the render captured no frame");
  double covered = 0.0;
  for (float a : result.frame->hairAlpha.values) covered += a;
  return covered / double(result.frame->hairAlpha.values.size());
}

// A head of radius 0.09 m (times 1/scale model units): 600 strands from the upper half of a sphere,
// out and then down 0.3 m, in 8 points. Z up maps model (x, y, z) so that z is up.
HairFileData syntheticHead(float unitsPerMetre, bool zUp) {
  HairFileData d;
  d.strandCount = 600;
  d.defaultSegments = 7;
  const float golden = 3.14159265f * (3.0f - std::sqrt(5.0f));
  for (std::uint32_t s = 0; s < d.strandCount; ++s) {
    const float y = 1.0f - float(s + 0.5f) / float(d.strandCount), r = std::sqrt(1.0f - y * y);
    const glm::vec3 n(r * std::sin(golden * s), y, r * std::cos(golden * s));
    glm::vec3 p = 0.09f * n;
    for (int k = 0; k < 8; ++k) {
      const glm::vec3 q = (zUp ? glm::vec3(p.x, -p.z, p.y) : p) * unitsPerMetre;
      d.points.push_back(q);
      p += 0.3f / 7.0f * glm::normalize(0.4f * n + glm::vec3(0.0f, -1.0f, 0.0f));
    }
  }
  return d;
}

double hairFraction(const RenderResult& img) {
  std::size_t hair = 0;
  for (std::size_t p = 0; p < img.rgba.size(); p += 4)
    for (int c = 0; c < 3; ++c)
      if (std::abs(int(img.rgba[p + c]) - int(img.rgba[c])) > 8) {
        ++hair;
        break;
      }
  return double(hair) / double(img.rgba.size() / 4);
}
}  // namespace

TEST_F(VulkanTest, ModelsInAnyUnitsAndUpAxisAreGuessedAndFramed) {
  const auto dir = std::filesystem::temp_directory_path() / "hairpipe_framing_test";
  std::filesystem::create_directories(dir);
  struct Case {
    const char* units;
    float perMetre;
  };
  for (const Case c : {Case{"mm", 1000.0f}, Case{"cm", 100.0f}, Case{"m", 1.0f}})
    for (bool zUp : {false, true}) {
      const std::string name = std::string(c.units) + (zUp ? "_z" : "_y");
      const auto path = dir / (name + ".hair");
      writeHairFile(path, syntheticHead(c.perMetre, zUp));
      const ModelGuess guess = guessModelFileTransform(path);
      EXPECT_EQ(guess.units, c.units) << name << ": " << guess.reason;
      EXPECT_EQ(guess.transform.up, zUp ? UpAxis::Z : UpAxis::Y) << name << ": " << guess.reason;
      EXPECT_TRUE(guess.unitsGuessed && guess.upGuessed);
      RenderRequest r;
      r.scene.model.kind = ModelSpec::Kind::Hair;
      r.scene.model.path = path;
      r.scene.model.transform = guess.transform;
      r.scene.density.totalStrands = 3000;
      r.scene.render = {kFramingWidth, kFramingHeight, 1};
      r.settleFrames = 0;
      r.opacity.enabled = false;
      r.look.ambient = 0.4f;  // hair facing away from the light shows through the ambient (sky albedo x 0.15)
      HairAsset asset = buildSceneAsset(r.scene);
      EXPECT_TRUE(asset.fittedCollider && asset.head.positions.empty()) << name;  // the fitted sphere is not drawn
      fitCameraToPoints(r.scene.camera, asset.guides.positions);
      ASSERT_GT(pointsInView(r.scene.camera, float(kFramingWidth) / kFramingHeight, asset.guides.positions), 0u);
      const double fraction = hairFraction(renderStill(*ctx, asset, r));
      EXPECT_GT(fraction, 0.05) << name;
      EXPECT_LT(fraction, 0.80) << name;
    }
  // A camera looking away sees no hair.
  CameraSpec away;
  away.target = {100.0f, 0.0f, 0.0f};
  const HairFileData d = syntheticHead(1.0f, false);
  EXPECT_EQ(pointsInView(away, 4.0f / 3.0f, d.points), 0u);
  std::filesystem::remove_all(dir);
}

namespace {
// A mohawk: 300 strands from a strip 1 cm wide along the crown of an uneven 9 cm head (front to back),
// standing out 12 cm in 6 points.
HairFileData mohawk() {
  HairFileData d;
  d.strandCount = 300;
  d.defaultSegments = 5;
  for (std::uint32_t s = 0; s < d.strandCount; ++s) {
    const float along = -0.8f + 1.6f * float(s / 3) / 99.0f, across = 0.05f * (float(s % 3) - 1.0f);
    const glm::vec3 n = glm::normalize(glm::vec3(std::sin(across), std::cos(along), std::sin(along)));
    const float scalp = 0.09f + 0.003f * std::sin(7.0f * along + 3.0f * float(s % 3));  // an uneven scalp
    for (int k = 0; k < 6; ++k) d.points.push_back(scalp * n + 0.024f * float(k) * n);
  }
  return d;
}
}  // namespace

// Without a mesh the importer fits a sphere to the roots and only collides with it (no head is drawn), and
// the mohawk's hair is in view (coverage through the exported hair alpha); with the head given (the 9 cm
// sphere as a scene collider, drawn) it shows too. Measured on lavapipe: 0.076 of the frame either way.
// (This strip's fitted sphere is a good one, 8.6 cm; a public mohawk's fit was 0.53 model units and, drawn,
// hid the hair: not drawing fitted spheres is what keeps that from happening.)
TEST_F(VulkanTest, AMohawkWithoutAMeshShowsItsHair) {
  const HairFileData data = mohawk();
  for (bool given : {false, true}) {
    HairImportOptions options;
    if (given) options.colliders = std::vector<SphereCollider>{{glm::vec3(0.0f), 0.09f}};
    const HairAsset asset = importHairAsset(data, options, "mohawk.hair");
    EXPECT_EQ(asset.head.positions.empty(), !given);
    RenderRequest r = coverageRequest();
    fitCameraToPoints(r.scene.camera, asset.guides.positions);
    const double fraction = hairAlphaCoverage(renderStill(*ctx, asset, r));
    std::cout << (given ? "head given" : "no head") << ": hair covers " << fraction << " of the frame\n";
    EXPECT_GT(fraction, 0.03) << (given ? "head given" : "no head");
  }
}

// With a character mesh (a 9 cm sphere .glb beside the .hair, as a scene gives it) the mesh is drawn as the
// head and is the only collider (no fitted sphere), every root binds to it within 4 mm (the uneven scalp's
// 3 mm plus the facets' sag), and the mohawk's hair is in view: 0.077 of the frame on lavapipe.
TEST_F(VulkanTest, AMohawkOnASphereMeshShowsItsHair) {
  const test::TempDir dir;
  writeHairFile(dir / "mohawk.hair", mohawk());
  test::writeBytes(dir / "head.glb", test::glbBytes(test::uvSphere(0.09f)));
  Scene scene;
  scene.model.kind = ModelSpec::Kind::Hair;
  scene.model.path = dir / "mohawk.hair";
  scene.mesh = CharacterMeshSpec{dir / "head.glb"};
  const HairAsset asset = buildSceneAsset(scene);
  ASSERT_TRUE(asset.character);
  EXPECT_EQ(asset.head.positions.size(), asset.character->positions.size());
  EXPECT_TRUE(asset.colliders.empty());
  EXPECT_FALSE(asset.fittedCollider);
  ASSERT_TRUE(asset.sdf);
  EXPECT_LT(asset.sdf->sample(glm::vec3(0.0f)), -0.08f);  // the sphere's inside
  EXPECT_EQ(asset.rootBindings.farRoots, 0u);
  EXPECT_LT(asset.rootBindings.maxDistance, 0.004f);
  RenderRequest r = coverageRequest();
  fitCameraToPoints(r.scene.camera, asset.guides.positions);
  const double fraction = hairAlphaCoverage(renderStill(*ctx, asset, r));
  std::cout << "mesh given: hair covers " << fraction << " of the frame\n";
  EXPECT_GT(fraction, 0.03);
}

namespace {
// A fringe: 100 guides from two rows across the forehead of a 9 cm head (57 degrees either side of the
// front, 4.6 degrees apart), hanging forward and down 9 cm in 7 points.
HairFileData fringe() {
  HairFileData d;
  d.strandCount = 100;
  d.defaultSegments = 6;
  for (std::uint32_t s = 0; s < d.strandCount; ++s) {
    const float around = -1.0f + 2.0f * float(s / 2) / 49.0f, up = 0.55f + 0.08f * float(s % 2);
    const glm::vec3 n(std::sin(around) * std::cos(up), std::sin(up), std::cos(around) * std::cos(up));
    glm::vec3 p = 0.09f * n;
    for (int k = 0; k < 7; ++k, p += 0.015f * glm::normalize(n + glm::vec3(0.0f, -1.5f, 0.0f))) d.points.push_back(p);
  }
  return d;
}
}  // namespace

// A partial groom stays partial: the fringe's roots are triangulated only where they are (every scalp
// triangle's centroid within 2 cm of a root, the roots being 0.5-0.9 cm apart; measured 0.26 cm; keeping
// every hull triangle gives 2.7 cm), and with the head given (drawn) its hair covers the frame from the front
// (0.15 on lavapipe) and none of the back of the head (0.0008: tips at the silhouette).
TEST_F(VulkanTest, AFringeStaysAFringe) {
  HairImportOptions options;
  options.colliders = std::vector<SphereCollider>{{glm::vec3(0.0f), 0.09f}};
  options.density.totalStrands = 3000;
  const HairAsset asset = importHairAsset(fringe(), options, "fringe.hair");
  const std::vector<glm::vec3> roots = asset.guides.roots();
  double farthest = 0.0;
  for (const glm::uvec3& t : asset.topology.triangles) {
    const glm::vec3 centroid = (roots[t.x] + roots[t.y] + roots[t.z]) / 3.0f;
    double nearest = 1e30;
    for (const glm::vec3& r : roots) nearest = std::min(nearest, double(glm::length(centroid - r)));
    farthest = std::max(farthest, nearest);
  }
  std::cout << "scalp triangles " << asset.topology.triangles.size() << ", farthest centroid from a root " << farthest
            << " m\n";
  EXPECT_LT(farthest, 0.02);
  double coverage[2];
  for (int back = 0; back < 2; ++back) {
    RenderRequest r = coverageRequest();
    r.scene.camera.target = glm::vec3(0.0f);
    r.scene.camera.distance = 0.5f;
    r.scene.camera.orbitDeg = back ? 180.0f : 0.0f;
    coverage[back] = hairAlphaCoverage(renderStill(*ctx, asset, r));
  }
  std::cout << "fringe hair covers " << coverage[0] << " of the frame from the front, " << coverage[1]
            << " from behind\n";
  EXPECT_GT(coverage[0], 0.03);
  EXPECT_LT(coverage[1], 0.002);
}

TEST(ModelGuess, GivenUnitsAndUpAreKeptAndBadUnitsRefused) {
  const HairFileData d = syntheticHead(100.0f, true);
  std::vector<glm::vec3> roots, tips;
  for (std::uint32_t s = 0; s < d.strandCount; ++s) roots.push_back(d.points[s * 8]), tips.push_back(d.points[s * 8 + 7]);
  const ModelGuess g = guessModelTransform(roots, tips, std::string("mm"), UpAxis::Y);
  EXPECT_EQ(g.transform.scale, 0.001f);
  EXPECT_EQ(g.transform.up, UpAxis::Y);
  EXPECT_FALSE(g.unitsGuessed || g.upGuessed);
  EXPECT_THROW(unitScale("inch"), Error);
  EXPECT_THROW(guessModelTransform({}, {}), Error);
}
