// The public API (engine/include/hairpipe/) through its own headers only: every documented failure comes
// back as a value whose message names the call and the problem (nothing throws: the calls are noexcept,
// so a throw would end the test process), and a frame records under validation without a message.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <vector>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <limits>
#include <optional>
#include <string>

#include "hairpipe/hairpipe.h"
#include "tests/api/validated_context.h"

namespace {
using ::testing::HasSubstr;

class PublicApi : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    hairpipe::Result<hairpipe::Asset> a = hairpipe::defaultHeadAsset({hairpipe::Density::Mode::Total, 8, 500, 7});
    ASSERT_TRUE(a.ok()) << a.message();
    asset_ = new hairpipe::Asset(std::move(a).value());
  }
  static void TearDownTestSuite() { delete asset_; }
  void SetUp() override {
    ASSERT_NO_FATAL_FAILURE(hairpipe::test::createValidatedContext(ctx_));
    hairpipe::RendererSettings s;
    s.formats = {VK_FORMAT_R8G8B8A8_UNORM, VK_FORMAT_D32_SFLOAT, VK_SAMPLE_COUNT_1_BIT};
    hairpipe::Result<hairpipe::Renderer> r = hairpipe::Renderer::create(*ctx_, s);
    ASSERT_TRUE(r.ok()) << r.message();
    renderer_.emplace(std::move(r).value());
  }
  void TearDown() override {
    renderer_.reset();
    if (ctx_) hairpipe::test::expectIdleAndSilent(*ctx_);
  }
  hairpipe::Instance instance(const hairpipe::InstanceSettings& s = {}) {
    hairpipe::Result<hairpipe::Instance> i = renderer_->createInstance(*asset_, s);
    EXPECT_TRUE(i.ok()) << i.message();
    return std::move(i).value();
  }
  static hairpipe::Asset* asset_;
  std::optional<hairpipe::Context> ctx_;
  std::optional<hairpipe::Renderer> renderer_;
};
hairpipe::Asset* PublicApi::asset_ = nullptr;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

template <class T>
std::string failureOf(const T& result) {
  EXPECT_FALSE(result.ok());
  return result.ok() ? std::string("(succeeded)") : result.message();
}

TEST(PublicApiWithoutDevice, AdoptRefusesMissingHandlesByName) {
  const std::string m = failureOf(hairpipe::Context::adopt({}));
  EXPECT_THAT(m, HasSubstr("hairpipe::Context::adopt"));
  EXPECT_THAT(m, HasSubstr("getInstanceProcAddr"));
  EXPECT_THAT(failureOf(hairpipe::unfitReasons(nullptr, VK_NULL_HANDLE, VK_NULL_HANDLE)),
              HasSubstr("hairpipe::unfitReasons: getInstanceProcAddr, instance and physicalDevice must be set"));
  const hairpipe::Result<std::vector<std::string>> needs = hairpipe::requirements();
  ASSERT_TRUE(needs.ok());
  EXPECT_EQ(needs.value().front(), "Vulkan 1.3");
}

TEST(PublicApiWithoutDevice, AssetsAndHelpersRefuseBadInputByName) {
  hairpipe::AssetSource source;
  source.path = "/nonexistent/groom.tfx";
  EXPECT_THAT(failureOf(hairpipe::loadAsset(source)), HasSubstr("/nonexistent/groom.tfx"));
  source.path = "groom.fbx";
  EXPECT_THAT(failureOf(hairpipe::loadAsset(source)), HasSubstr("expected a path ending in .hair, .tfx or .obj"));
  source.path = "/nonexistent/groom.hair";
  source.scale = -1.0f;
  EXPECT_THAT(failureOf(hairpipe::loadAsset(source)), HasSubstr("scale"));
  hairpipe::Density density;
  density.totalStrands = 0;
  EXPECT_THAT(failureOf(hairpipe::defaultHeadAsset(density)), HasSubstr("hairpipe::defaultHeadAsset"));
  EXPECT_THAT(failureOf(hairpipe::absorptionFromColor(0.5f, 1.5f, 0.5f)), HasSubstr("color"));
  hairpipe::Camera camera;
  camera.fovY = 4.0f;
  EXPECT_THAT(failureOf(hairpipe::makeView(camera, {64, 64})), HasSubstr("fovY"));
  camera = {};
  camera.up = {0.0f, 0.0f, 1.0f};  // along the view direction
  EXPECT_THAT(failureOf(hairpipe::makeView(camera, {64, 64})), HasSubstr("up is parallel"));
  EXPECT_THAT(failureOf(hairpipe::makeView({}, {0, 64})), HasSubstr("extent"));
  EXPECT_THAT(failureOf(hairpipe::loadTfxBoneSkinning("/nonexistent/hair.tfxbone", 10)),
              HasSubstr("hairpipe::loadTfxBoneSkinning: /nonexistent/hair.tfxbone"));
  EXPECT_STREQ(hairpipe::versionString(), "0.2.0");
}

// makeView's projection maps the near plane to depth 0 and the far one to 1, or with Camera::reversedDepth
// the other way round (what AttachmentFormats::reversedDepth expects of every view).
TEST(PublicApiWithoutDevice, MakeViewReversesDepthOnRequest) {
  hairpipe::Camera camera;  // eye at z = 1 looking at the origin
  camera.nearZ = 0.1f;
  camera.farZ = 10.0f;
  const auto depthAt = [](const hairpipe::View& v, float distance) {  // along the view axis, in front of the eye
    const float* p = v.projection.m;  // column-major: element (row r, column c) at p[c * 4 + r]
    const float zView = -distance;   // view space looks down -z
    return (p[10] * zView + p[14]) / (p[11] * zView + p[15]);
  };
  const hairpipe::Result<hairpipe::View> forward = hairpipe::makeView(camera, {64, 64});
  camera.reversedDepth = true;
  const hairpipe::Result<hairpipe::View> reversed = hairpipe::makeView(camera, {64, 64});
  ASSERT_TRUE(forward.ok() && reversed.ok());
  EXPECT_NEAR(depthAt(forward.value(), 0.1f), 0.0f, 1e-5f);
  EXPECT_NEAR(depthAt(forward.value(), 10.0f), 1.0f, 1e-5f);
  EXPECT_NEAR(depthAt(reversed.value(), 0.1f), 1.0f, 1e-5f);
  EXPECT_NEAR(depthAt(reversed.value(), 10.0f), 0.0f, 1e-5f);
}

// The studio splits into its two bright regions as lights, the rim (brightest) first, and SH for the rest,
// which a look takes; an image that is not an environment is refused naming the problem.
TEST(PublicApiWithoutDevice, EnvironmentLightingSplitsTheStudioAndRefusesBadImages) {
  hairpipe::Result<hairpipe::EnvironmentImage> studio = hairpipe::studioEnvironment();
  ASSERT_TRUE(studio.ok()) << studio.message();
  EXPECT_EQ(studio.value().texels.size(), std::size_t(studio.value().width) * studio.value().height);
  hairpipe::Result<hairpipe::EnvironmentLighting> lit = hairpipe::environmentLighting(studio.value());
  ASSERT_TRUE(lit.ok()) << lit.message();
  ASSERT_EQ(lit.value().lights.size(), 2u);
  EXPECT_LT(lit.value().lights[0].direction.z, 0.0f);  // the rim, behind
  EXPECT_GT(lit.value().lights[1].direction.z, 0.0f);  // the soft box, in front
  for (const hairpipe::Light& l : lit.value().lights) EXPECT_TRUE(l.shadows && l.intensity > 0.0f);
  EXPECT_GT(lit.value().harmonics[0].y, 0.0f);  // the room
  EXPECT_EQ(hairpipe::environmentLighting(studio.value(), 0).value().lights.size(), 0u);
  hairpipe::EnvironmentImage bad = studio.value();
  bad.texels[7].x = -1.0f;
  EXPECT_THAT(failureOf(hairpipe::environmentLighting(bad)), HasSubstr("negative"));
  bad = studio.value();
  bad.width += 1;
  EXPECT_THAT(failureOf(hairpipe::environmentLighting(bad)), HasSubstr("number of texels"));
  EXPECT_THAT(failureOf(hairpipe::environmentLighting(studio.value(), 9)), HasSubstr("environment lights"));
  EXPECT_THAT(failureOf(hairpipe::environmentLighting({})), HasSubstr("hairpipe::environmentLighting"));
}

TEST_F(PublicApi, RendererSettingsAreRefusedByField) {
  hairpipe::RendererSettings s;
  s.framesInFlight = 9;
  EXPECT_THAT(failureOf(hairpipe::Renderer::create(*ctx_, s)), HasSubstr("framesInFlight"));
  s = {};
  s.maxViewsPerFrame = 0;
  EXPECT_THAT(failureOf(hairpipe::Renderer::create(*ctx_, s)), HasSubstr("maxViewsPerFrame"));
  s = {};
  s.shadowedLights = 5;
  EXPECT_THAT(failureOf(hairpipe::Renderer::create(*ctx_, s)), HasSubstr("shadowedLights must be in [1, 4], got 5"));
  s = {};
  s.opacity.resolution = 8;
  EXPECT_THAT(failureOf(hairpipe::Renderer::create(*ctx_, s)), HasSubstr("resolution"));
  s = {};
  s.shadingSpacing = -1.0f;
  EXPECT_THAT(failureOf(hairpipe::Renderer::create(*ctx_, s)), HasSubstr("shadingSpacing must be in [0, 4096]"));
  s = {};
  s.formats.depth = VK_FORMAT_R32_SFLOAT;
  EXPECT_THAT(failureOf(hairpipe::Renderer::create(*ctx_, s)), HasSubstr("formats.depth must be a depth format"));
  s = {};
  s.formats.stencil = VK_FORMAT_D32_SFLOAT_S8_UINT;  // with a depth format that has no stencil
  EXPECT_THAT(failureOf(hairpipe::Renderer::create(*ctx_, s)), HasSubstr("formats.stencil must be VK_FORMAT_UNDEFINED"));
  s = {};
  s.formats.color = VK_FORMAT_D32_SFLOAT;
  EXPECT_THAT(failureOf(hairpipe::Renderer::create(*ctx_, s)), HasSubstr("formats.color must be a colour format"));
  s = {};
  s.formats.samples = VkSampleCountFlagBits(3);
  EXPECT_THAT(failureOf(hairpipe::Renderer::create(*ctx_, s)), HasSubstr("samples must be 1, 2, 4, 8 or 16, got 3"));
  s = {};
  s.formats.color = VK_FORMAT_R32G32B32A32_UINT;  // an integer format: no blending on any device
  EXPECT_THAT(failureOf(hairpipe::Renderer::create(*ctx_, s)), HasSubstr("is not a blendable colour attachment on"));
  s = {};
  s.pipelineCache.assign(12, 0);
  EXPECT_THAT(failureOf(hairpipe::Renderer::create(*ctx_, s)),
              HasSubstr("pipeline cache data of 12 bytes is shorter than its 32-byte header"));
  s.pipelineCache.assign(64, 0);
  s.pipelineCache[0] = 200;  // the header's own size, past the data
  EXPECT_THAT(failureOf(hairpipe::Renderer::create(*ctx_, s)), HasSubstr("its header says 200 bytes, of 64"));
}

// The pipeline cache goes out and comes back: a Renderer that built its pipelines (one instance) hands out
// data with this device's header and more than the header; a Renderer started from it works; one started
// from the same data with another device's UUID ignores it and works too.
TEST_F(PublicApi, PipelineCacheDataRoundTrips) {
  hairpipe::Instance first = instance();
  const hairpipe::Result<std::vector<std::uint8_t>> data = renderer_->pipelineCacheData();
  ASSERT_TRUE(data.ok()) << data.message();
  ASSERT_GE(data->size(), 32u);
  std::uint32_t headerSize = 0, version = 0;
  std::memcpy(&headerSize, data->data(), 4);
  std::memcpy(&version, data->data() + 4, 4);
  EXPECT_EQ(version, std::uint32_t(VK_PIPELINE_CACHE_HEADER_VERSION_ONE));
  EXPECT_GE(headerSize, 32u);
  std::cout << "pipeline cache after one instance: " << data->size() << " bytes\n";
  for (bool otherDevice : {false, true}) {
    hairpipe::RendererSettings s;
    s.formats = {VK_FORMAT_R8G8B8A8_UNORM, VK_FORMAT_D32_SFLOAT, VK_SAMPLE_COUNT_1_BIT};
    s.pipelineCache = data.value();
    if (otherDevice) s.pipelineCache[16] ^= 0xff;  // another pipelineCacheUUID
    hairpipe::Result<hairpipe::Renderer> again = hairpipe::Renderer::create(*ctx_, s);
    ASSERT_TRUE(again.ok()) << again.message();
    hairpipe::Result<hairpipe::Instance> second = again->createInstance(*asset_, {});
    EXPECT_TRUE(second.ok()) << second.message();
  }
}

// A .hair file of 81 strands on a 10 cm head's crown, 1 cm apart, each laid 2 mm off the head over 80 degrees
// of arc toward +x or -x by the side of x = 0 its root is on: a parting along z.
std::string writePartedCrown() {
  std::vector<float> points;
  for (int i = 0; i < 9; ++i)
    for (int j = 0; j < 9; ++j) {
      const float rx = 0.01f * float(i - 4) + 0.005f, ry = 0.1f, rz = 0.01f * float(j - 4);
      const float rl = std::sqrt(rx * rx + ry * ry + rz * rz);
      const float r[3] = {rx / rl, ry / rl, rz / rl}, side = rx >= 0.0f ? 1.0f : -1.0f;
      float s[3] = {side - side * r[0] * r[0], -side * r[0] * r[1], -side * r[0] * r[2]};  // side's tangent part
      const float sl = std::sqrt(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]);
      for (int k = 0; k < 7; ++k) {
        const float a = 1.3962634f * float(k) / 6.0f, radius = 0.1f + (k > 0 ? 0.002f : 0.0f);
        for (int c = 0; c < 3; ++c) points.push_back(radius * (std::cos(a) * r[c] + std::sin(a) * s[c] / sl));
      }
    }
  unsigned char header[128] = {};
  const std::uint32_t fields[5] = {81, 81 * 7, 2, 6, 0};  // strands, points, flags (points), segments
  std::memcpy(header, "HAIR", 4);
  std::memcpy(header + 4, fields, sizeof fields);
  const std::string path = ::testing::TempDir() + "hairpipe_api_parted.hair";
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) return "";
  std::fwrite(header, 1, sizeof header, f);
  std::fwrite(points.data(), sizeof(float), points.size(), f);
  std::fclose(f);
  return path;
}

TEST(PublicApiFiles, AnImportedPartingIsLeftBare) {
  const std::string path = writePartedCrown();
  ASSERT_FALSE(path.empty());
  hairpipe::AssetSource source;
  source.path = path;
  source.density = {hairpipe::Density::Mode::Total, 8, 2000, 7};
  const hairpipe::Result<hairpipe::Asset> asset = hairpipe::loadAsset(source);
  ASSERT_TRUE(asset.ok()) << asset.message();
  EXPECT_GT(asset.value().bareScalpTriangleCount(), 0u);
  EXPECT_EQ(asset.value().strandCount(), 2000u);  // the density is spread over the triangles kept
  const hairpipe::Result<hairpipe::Asset> denser = asset.value().withDensity({hairpipe::Density::Mode::Total, 8, 4000, 7});
  ASSERT_TRUE(denser.ok()) << denser.message();
  EXPECT_EQ(denser.value().bareScalpTriangleCount(), asset.value().bareScalpTriangleCount());
  const hairpipe::Result<hairpipe::Asset> head = hairpipe::defaultHeadAsset({hairpipe::Density::Mode::Total, 8, 500, 7});
  ASSERT_TRUE(head.ok()) << head.message();
  EXPECT_EQ(head.value().bareScalpTriangleCount(), 0u);
  std::remove(path.c_str());
}

// A TressFX skinning file as the application gets it: bone names and per-guide weights for ScalpInput::skin.
TEST(PublicApiFiles, TressFxSkinningLoadsForEveryGuide) {
  std::vector<unsigned char> bytes;
  auto i32 = [&](std::int32_t v) {
    unsigned char b[4];
    std::memcpy(b, &v, 4);
    bytes.insert(bytes.end(), b, b + 4);
  };
  auto f32 = [&](float v) {
    std::int32_t i;
    std::memcpy(&i, &v, 4);
    i32(i);
  };
  i32(2);  // bones: index, name length with its NUL, name
  for (const char* name : {"head", "jaw"}) {
    i32(0);
    i32(std::int32_t(std::strlen(name) + 1));
    bytes.insert(bytes.end(), name, name + std::strlen(name) + 1);
  }
  i32(2);  // strands: index, 4 x (bone, weight)
  for (int s = 0; s < 2; ++s) {
    i32(s);
    i32(0), f32(s == 0 ? 1.0f : 1.0f), i32(s == 0 ? -1 : 1), f32(s == 0 ? 0.0f : 3.0f);
    i32(-1), f32(0.0f), i32(-1), f32(0.0f);
  }
  const std::string path = ::testing::TempDir() + "hairpipe_api.tfxbone";
  std::FILE* f = std::fopen(path.c_str(), "wb");
  ASSERT_NE(f, nullptr);
  std::fwrite(bytes.data(), 1, bytes.size(), f);
  std::fclose(f);
  auto skinning = hairpipe::loadTfxBoneSkinning(path, 3);
  ASSERT_TRUE(skinning.ok()) << skinning.message();
  EXPECT_EQ(skinning.value().boneNames, (std::vector<std::string>{"head", "jaw"}));
  ASSERT_EQ(skinning.value().skin.size(), 3u);
  EXPECT_EQ(skinning.value().skin[0].weights[0], 1.0f);
  EXPECT_EQ(skinning.value().skin[1].bones[1], 1u);
  EXPECT_FLOAT_EQ(skinning.value().skin[1].weights[1], 0.75f);  // 1 and 3, normalised
  EXPECT_EQ(skinning.value().skin[2].weights, skinning.value().skin[1].weights);
  EXPECT_THAT(failureOf(hairpipe::loadTfxBoneSkinning(path, 1)), HasSubstr("2 strands of skinning for 1 guides"));
  std::remove(path.c_str());
}

TEST_F(PublicApi, InstanceSettingsAndSettersAreRefusedByField) {
  hairpipe::InstanceSettings bad;
  bad.material.eta = std::nan("");
  EXPECT_THAT(failureOf(renderer_->createInstance(*asset_, bad)), HasSubstr("hairpipe::Renderer::createInstance"));
  bad = {};
  bad.scalp.kind = hairpipe::ScalpInput::Kind::Bones;
  bad.scalp.boneCount = 1;  // no weights for the guides
  EXPECT_THAT(failureOf(renderer_->createInstance(*asset_, bad)), HasSubstr("skin"));

  hairpipe::Instance head = instance();
  hairpipe::Material m;
  m.absorption[1] = -1.0;
  EXPECT_THAT(failureOf(head.setMaterial(m, hairpipe::FibreModel::Physical)), HasSubstr("hairpipe::Instance::setMaterial"));
  m = {};
  m.tiltVariation = 0.5;  // 29 degrees: beyond the 10 allowed
  EXPECT_THAT(failureOf(head.setMaterial(m, hairpipe::FibreModel::Physical)), HasSubstr("tiltVariation"));
  m = {};
  m.roughnessVariation = 0.3;  // beyond the 0.25 allowed
  EXPECT_THAT(failureOf(head.setMaterial(m, hairpipe::FibreModel::Physical)), HasSubstr("roughnessVariation"));
  hairpipe::LookSettings look;
  look.strandWidth = kNaN;
  EXPECT_THAT(failureOf(head.setLook(look)), HasSubstr("strand width"));
  look = {};
  look.environment[4].y = kNaN;
  EXPECT_THAT(failureOf(head.setLook(look)), HasSubstr("environment coefficients"));
  hairpipe::SimulationSettings sim;
  sim.dt = 0.0;
  EXPECT_THAT(failureOf(head.setSimulation(sim)), HasSubstr("dt"));
  sim = {};
  sim.friction = 1.5;
  EXPECT_THAT(failureOf(head.setSimulation(sim)), HasSubstr("friction"));
  sim = {};
  sim.gridResolution = 64;  // the hair grid's cells are fixed when the instance is created
  EXPECT_THAT(failureOf(head.setSimulation(sim)), HasSubstr("gridResolution is fixed"));
  sim = {};
  sim.volume = 0.6;  // turning the grid on between frames is allowed
  sim.friction = 0.1;
  EXPECT_TRUE(head.setSimulation(sim).ok());
  hairpipe::HeadMotion motion;
  motion.to.m[12] = kNaN;
  EXPECT_THAT(failureOf(head.setMotion(motion)), HasSubstr("hairpipe::Instance::setMotion"));
  hairpipe::Density density;
  density.totalStrands = 0;
  EXPECT_THAT(failureOf(head.setDensity(density)), HasSubstr("hairpipe::Instance::setDensity"));
  hairpipe::LodSettings lod;
  lod.endDistance = lod.startDistance;
  EXPECT_THAT(failureOf(head.setLod(lod)), HasSubstr("hairpipe::Instance::setLod: LodSettings: the distances"));
  lod = {};
  lod.minFraction = 0.0f;
  EXPECT_THAT(failureOf(head.setLod(lod)), HasSubstr("LodSettings.minFraction must be in [0.001, 1], got 0"));
  lod.minFraction = 1e-9f;  // widened a billion times (and 0 in the blend's float arithmetic)
  EXPECT_THAT(failureOf(head.setLod(lod)), HasSubstr("LodSettings.minFraction must be in [0.001, 1], got 1e-09"));
  bad = {};
  bad.lod.startDistance = kNaN;
  EXPECT_THAT(failureOf(renderer_->createInstance(*asset_, bad)), HasSubstr("LodSettings: the distances"));
  bad = {};
  bad.groom.curlRadius = 2.0f;
  EXPECT_THAT(failureOf(renderer_->createInstance(*asset_, bad)), HasSubstr("GroomSettings.curlRadius must be in [0"));
  hairpipe::GroomSettings groom;
  groom.frizzFrequency = 0.0f;
  EXPECT_THAT(failureOf(head.setGroom(groom)), HasSubstr("hairpipe::Instance::setGroom: GroomSettings.frizzFrequency"));
  groom = {};
  groom.frizzHairlineWidth = kNaN;
  EXPECT_THAT(failureOf(head.setGroom(groom)), HasSubstr("GroomSettings.frizzHairlineWidth must be in (0, 10]"));
  groom = {};
  groom.frizzAmplitude = 0.002f;
  groom.frizzHairline = 3.0f;
  EXPECT_TRUE(head.setGroom(groom).ok());
  groom = {};
  groom.curlRadius = 0.004f;
  groom.curlTurns = 30.0f;
  EXPECT_TRUE(head.setGroom(groom).ok());
  bad = {};
  bad.skinBounceSamples = 1;
  EXPECT_THAT(failureOf(renderer_->createInstance(*asset_, bad)),
              HasSubstr("skinBounceSamples must be in [2, 256], got 1"));
  EXPECT_THAT(failureOf(head.setRootFrames(VK_NULL_HANDLE, 0, 0)),
              HasSubstr("hairpipe::Instance::setRootFrames: setRootFrames: the scalp input is not RootFrames"));
  EXPECT_EQ(head.strandCount(), 500u);  // a refused setter changes nothing
}

TEST_F(PublicApi, RecordCallsRefuseBadFramesBeforeRecording) {
  hairpipe::Instance head = instance();
  hairpipe::Instance* heads[] = {&head};
  hairpipe::Instance* none[] = {nullptr};
  // Nothing is recorded for a refused call, so the command buffer is never used: a null handle suffices.
  EXPECT_THAT(failureOf(renderer_->recordUpdate(VK_NULL_HANDLE, 0, none)), HasSubstr("null"));
  hairpipe::Light light;
  light.direction = {0.0f, 0.0f, 0.0f};
  EXPECT_THAT(failureOf(renderer_->recordShadows(VK_NULL_HANDLE, 0, light, heads)), HasSubstr("direction"));
  std::vector<hairpipe::Light> lights(9);
  EXPECT_THAT(failureOf(renderer_->recordShadows(VK_NULL_HANDLE, 0, lights, heads)), HasSubstr("at most 8 lights, got 9"));
  lights.resize(2);
  lights[1].type = hairpipe::Light::Type::Point;
  lights[1].range = -1.0f;
  EXPECT_THAT(failureOf(renderer_->recordShadows(VK_NULL_HANDLE, 0, lights, heads)), HasSubstr("point light range"));
  hairpipe::View view;
  view.index = 4;  // maxViewsPerFrame is 4
  EXPECT_THAT(failureOf(renderer_->recordDraw(VK_NULL_HANDLE, 0, view, heads)), HasSubstr("index"));
  view.index = 0;
  view.fovY = -0.5f;
  EXPECT_THAT(failureOf(renderer_->recordDraw(VK_NULL_HANDLE, 0, view, heads)), HasSubstr("View.fovY must be in (0, pi) radians, got -0.5"));
  view.fovY = 0.6f;  // the default View's identity projection keeps depth rising with distance ahead: not forward
  EXPECT_THAT(failureOf(renderer_->recordDraw(VK_NULL_HANDLE, 0, view, heads)),
              HasSubstr("View.projection maps depth reversed (near to 1), but RendererSettings.formats.reversedDepth is false"));
  EXPECT_THAT(failureOf(renderer_->setRasterTarget({64, 64}, VK_NULL_HANDLE, heads)), HasSubstr("not compute"));
  EXPECT_THAT(failureOf(renderer_->recordRaster(VK_NULL_HANDLE, 0, hairpipe::View{})), HasSubstr("setRasterTarget"));
  EXPECT_THAT(failureOf(renderer_->createRasterTarget({64, 64}, VK_NULL_HANDLE, heads)),
              HasSubstr("hairpipe::Renderer::createRasterTarget: Renderer: a raster target needs the compute raster"));
  EXPECT_EQ(renderer_->raster(), hairpipe::RasterMode::Graphics);
}

TEST_F(PublicApi, AComputeRasterTargetWithoutADepthViewIsRefused) {
  hairpipe::RendererSettings s;
  s.formats = {VK_FORMAT_R8G8B8A8_UNORM, VK_FORMAT_D32_SFLOAT, VK_SAMPLE_COUNT_1_BIT};
  s.raster = hairpipe::RasterMode::Compute;
  hairpipe::Result<hairpipe::Renderer> r = hairpipe::Renderer::create(*ctx_, s);
  ASSERT_TRUE(r.ok()) << r.message();
  hairpipe::Result<hairpipe::Instance> head = r.value().createInstance(*asset_, {});
  ASSERT_TRUE(head.ok()) << head.message();
  hairpipe::Instance* heads[] = {&head.value()};
  EXPECT_THAT(failureOf(r.value().setRasterTarget({64, 64}, VK_NULL_HANDLE, heads)), HasSubstr("the depth view is VK_NULL_HANDLE"));
  EXPECT_THAT(failureOf(r.value().recordRaster(VK_NULL_HANDLE, 0, hairpipe::View{})), HasSubstr("setRasterTarget"));
  EXPECT_THAT(failureOf(r.value().createRasterTarget({64, 64}, VK_NULL_HANDLE, heads)),
              HasSubstr("the depth view is VK_NULL_HANDLE"));
  hairpipe::Instance* none[] = {nullptr};
  EXPECT_THAT(failureOf(r.value().createRasterTarget({64, 64}, VK_NULL_HANDLE, none)),
              HasSubstr("an instance is null or was moved from"));
}

TEST_F(PublicApi, InstancesOfAnotherRendererAreRefused) {
  hairpipe::Result<hairpipe::Renderer> other = hairpipe::Renderer::create(*ctx_, {});
  ASSERT_TRUE(other.ok()) << other.message();
  hairpipe::Instance head = instance();
  hairpipe::Instance* heads[] = {&head};
  EXPECT_THAT(failureOf(other->recordUpdate(VK_NULL_HANDLE, 0, heads)), HasSubstr("another Renderer"));
}
TEST_F(PublicApi, MovedFromHandlesReturnFailuresAndInstancesOutliveTheirRenderer) {
  hairpipe::Instance head = instance();
  hairpipe::Instance* heads[] = {&head};
  hairpipe::Renderer taken = std::move(*renderer_);
  EXPECT_THAT(failureOf(renderer_->recordUpdate(VK_NULL_HANDLE, 0, heads)), HasSubstr("the Renderer was moved from"));
  EXPECT_THAT(failureOf(renderer_->createInstance(*asset_, {})), HasSubstr("the Renderer was moved from"));
  hairpipe::Instance other = std::move(head);
  EXPECT_THAT(failureOf(head.setLook({})), HasSubstr("the instance was moved from"));
  EXPECT_THAT(failureOf(head.materialStatus()), HasSubstr("hairpipe::Instance::materialStatus: the instance was moved from"));
  EXPECT_TRUE(other.materialStatus().ok());  // no material change failed
  EXPECT_EQ(head.strandCount(), 0u);
  hairpipe::Asset copy = *asset_;
  hairpipe::Asset emptied = std::move(copy);
  EXPECT_THAT(failureOf(copy.guideRoots()), HasSubstr("the Asset was moved from"));
  EXPECT_THAT(failureOf(hairpipe::prepareInstance(copy, {})), HasSubstr("hairpipe::prepareInstance: the Asset was moved from"));
  EXPECT_TRUE(hairpipe::prepareInstance(emptied, {}).ok());
  EXPECT_EQ(copy.guideCount(), 0u);
  EXPECT_EQ(emptied.guideCount(), asset_->guideCount());
  // The Renderer goes first: its instance keeps what it needs and still takes settings.
  { hairpipe::Renderer gone = std::move(taken); }
  EXPECT_TRUE(other.setLook({}).ok());
  EXPECT_EQ(other.strandCount(), 500u);
}

TEST_F(PublicApi, AnInstanceAssignedOverGivesWayToTheOther) {
  hairpipe::Instance a = instance();
  hairpipe::Density sparse;
  sparse.totalStrands = 200;
  hairpipe::Instance b = instance();
  ASSERT_TRUE(b.setDensity(sparse).ok());
  a = std::move(b);
  EXPECT_EQ(a.strandCount(), 200u);
  EXPECT_EQ(b.strandCount(), 0u);
  EXPECT_TRUE(a.setLook({}).ok());
  EXPECT_THAT(failureOf(b.setDensity(sparse)), HasSubstr("the instance was moved from"));
}

}  // namespace

// Renderer::hairShadows() hands out the maps an application's shaders read (tests/render/
// hair_shadows_export_test.cpp reads them on the device); its parameters follow setOpacityTuning, and an
// instance's forward term its look.
TEST_F(PublicApi, HairShadowsDescribeTheMapsAndFollowTheTuning) {
  hairpipe::Result<hairpipe::Renderer::HairShadows> shadows = renderer_->hairShadows();
  ASSERT_TRUE(shadows.ok()) << shadows.message();
  const hairpipe::OpacitySettings defaults;
  EXPECT_NE(shadows.value().image, VK_NULL_HANDLE);
  EXPECT_NE(shadows.value().view, VK_NULL_HANDLE);
  EXPECT_NE(shadows.value().sampler, VK_NULL_HANDLE);
  EXPECT_NE(shadows.value().lightSpaces, VK_NULL_HANDLE);
  EXPECT_EQ(shadows.value().resolution, defaults.resolution);
  EXPECT_EQ(shadows.value().slots, 1u);
  EXPECT_EQ(shadows.value().layersPerSlot, 5u);
  EXPECT_EQ(shadows.value().lightSpacesBytes, 128u);
  EXPECT_EQ(shadows.value().opacityScale, defaults.k);
  // lavapipe takes the compute path, where deep maps are the default: their bias is the one in effect.
  EXPECT_TRUE(shadows.value().deep);
  EXPECT_EQ(shadows.value().bias, defaults.deepBiasSlices);
  hairpipe::OpacitySettings tuned = defaults;
  tuned.k = 0.7f;
  tuned.biasSlices = 2.0f;
  tuned.deepBiasSlices = 0.5f;
  ASSERT_TRUE(renderer_->setOpacityTuning(tuned).ok());
  EXPECT_EQ(renderer_->hairShadows().value().opacityScale, 0.7f);
  EXPECT_EQ(renderer_->hairShadows().value().bias, 0.5f);
  tuned.enabled = false;
  ASSERT_TRUE(renderer_->setOpacityTuning(tuned).ok());
  EXPECT_EQ(renderer_->hairShadows().value().opacityScale, 0.0f);  // no hair shadow: T = 1
  EXPECT_EQ(renderer_->hairShadows().value().view, shadows.value().view);

  hairpipe::InstanceSettings single;
  single.look.scattering = hairpipe::Scattering::Single;
  hairpipe::Instance head = instance(single);
  EXPECT_EQ(head.hairShadowForward().value().weight, 0.0f);
  hairpipe::LookSettings dual;
  ASSERT_TRUE(head.setLook(dual).ok());
  const hairpipe::Instance::HairShadowForward forward = head.hairShadowForward().value();
  EXPECT_GT(forward.weight, 0.0f);
  EXPECT_GT(forward.albedo.x, forward.albedo.z);  // brown hair passes more red on
  hairpipe::Instance gone = std::move(head);
  EXPECT_THAT(failureOf(head.hairShadowForward()), HasSubstr("the instance was moved from"));
  hairpipe::Renderer taken = std::move(*renderer_);
  EXPECT_THAT(failureOf(renderer_->hairShadows()), HasSubstr("the Renderer was moved from"));
}
