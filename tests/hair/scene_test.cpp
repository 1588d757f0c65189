// Scene files: defaults, a full scene, every section's errors naming the JSON path, and building
// assets from .hair and .obj models. Also SimulationParams::validate.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "engine/core/hair/hair_file.h"
#include "engine/core/hair/scene.h"
#include "samples/tools/host/scene_file.h"
#include "samples/tools/host/synthetic_hair.h"
#include "tests/hair/hair_test_util.h"

namespace hp {
namespace {
Scene parseSceneText(const std::string& json) { return parseScene(json, "scene.json", "/base"); }
std::string sceneParseError(const std::string& json) {
  return test::errorOf([&] { parseSceneText(json); });
}

TEST(Scene, EmptyObjectIsTheDefaultScene) {
  Scene s = parseSceneText("{}");
  Scene d;
  EXPECT_EQ(s.model.kind, ModelSpec::Kind::Default);
  EXPECT_EQ(s.growth, d.growth);
  EXPECT_EQ(s.density, d.density);
  EXPECT_FALSE(s.colliders.has_value());
  EXPECT_EQ(s.material, HairMaterial{});
  EXPECT_EQ(s.render.msaa, 4u);
  EXPECT_EQ(s.render.raster, RasterMode::Auto);
  EXPECT_EQ(s.simulation.iterations, SimulationParams{}.iterations);
}

TEST(Scene, ReadsEverySection) {
  Scene s = parseSceneText(R"({
    "model": {"source": "models/curly.hair", "scale": 0.01, "up": "z", "translate": [0, -1.5, 0], "keepStrands": false},
    "growth": {"particles": 9, "length": 0.2, "lengthVariation": 0.1, "segmentRatio": 1.2, "bend": 0.3,
               "bendDirection": [0, -1, 0], "seed": 5},
    "density": {"strandsPerTriangle": 12, "seed": 3},
    "colliders": [{"center": [0, 0.1, 0], "radius": 0.09}],
    "material": {"eta": 1.6, "absorption": [0.2, 0.3, 0.4], "alphaRDeg": -5, "betaRDeg": 6, "kG": 0.4,
                 "wcDeg": 10, "dEta": 0.25, "dhM": 0.4, "tiltVariationDeg": 3, "roughnessVariation": 0.25},
    "light": {"direction": [0, 2, 0], "color": [1, 0.9, 0.8], "intensity": 2.5},
    "camera": {"orbitDeg": 45, "elevationDeg": 20, "distance": 1.2, "fovDeg": 40, "target": [0, 0.1, 0]},
    "render": {"width": 640, "height": 480, "msaa": 8, "raster": "graphics"},
    "simulation": {"dt": 0.01, "substeps": 3, "iterations": 12, "gravity": [0, -9.8, 0], "damping": 0.1,
                   "pearlRadius": 0.003, "stiffness": 0.2, "stiffnessFalloff": 0.5, "maxSpeed": 5,
                   "windDirection": [0, 0, 1], "windStrength": 2, "windGust": 0.5, "windGustFrequency": 1}
  })");
  EXPECT_EQ(s.render.raster, RasterMode::Graphics);
  EXPECT_EQ(s.model.kind, ModelSpec::Kind::Hair);
  EXPECT_EQ(s.model.path, std::filesystem::path("/base/models/curly.hair"));
  EXPECT_EQ(s.model.transform.scale, 0.01f);
  EXPECT_EQ(s.model.transform.up, UpAxis::Z);
  EXPECT_EQ(s.model.transform.translation, glm::vec3(0, -1.5f, 0));
  EXPECT_EQ(s.growth.particlesPerGuide, 9u);
  EXPECT_EQ(s.growth.seed, 5u);
  EXPECT_EQ(s.density.mode, DensityOptions::Mode::PerTriangle);
  EXPECT_EQ(s.density.strandsPerTriangle, 12u);
  ASSERT_TRUE(s.colliders.has_value());
  EXPECT_EQ(s.colliders->at(0).radius, 0.09f);
  EXPECT_NEAR(s.material.alphaR, glm::radians(-5.0), 1e-12);
  EXPECT_NEAR(s.material.tiltVariation, glm::radians(3.0), 1e-12);
  EXPECT_EQ(s.material.roughnessVariation, 0.25);
  EXPECT_NEAR(s.material.wc, glm::radians(10.0), 1e-12);
  EXPECT_EQ(s.material.absorption, glm::dvec3(0.2, 0.3, 0.4));
  ASSERT_EQ(s.lights.size(), 1u);  // "light": the one light
  EXPECT_EQ(s.lights[0].direction, glm::vec3(0, 1, 0));  // normalized
  EXPECT_EQ(s.lights[0].intensity, 2.5f);
  EXPECT_EQ(s.camera.fovDeg, 40.0f);
  EXPECT_EQ(s.render.width, 640u);
  EXPECT_EQ(s.simulation.substeps, 3u);
  EXPECT_EQ(s.simulation.windStrength, 2.0);
}

TEST(Scene, ModelShorthandAndDensityTotal) {
  Scene s = parseSceneText(R"({"model": "scalp.OBJ", "density": {"totalStrands": 500}})");
  EXPECT_EQ(s.model.kind, ModelSpec::Kind::Obj);
  EXPECT_EQ(s.density.mode, DensityOptions::Mode::Total);
  EXPECT_EQ(s.density.totalStrands, 500u);
}

TEST(Scene, SyntaxErrorNamesFileAndPosition) {
  EXPECT_THAT_ERROR_CONTAINS_IMPL(sceneParseError("{\"render\": {\"width\": 5,}}"), "scene.json: invalid JSON: ");
  EXPECT_THAT_ERROR_CONTAINS_IMPL(sceneParseError("{\"render\": "), "line 1, column 12");
}

TEST(Scene, WrongTypesNameThePath) {
  EXPECT_THAT_ERROR_CONTAINS_IMPL(sceneParseError(R"({"simulation": {"dt": "fast"}})"),
                                  "scene.json: /simulation/dt: expected a number, got string");
  EXPECT_THAT_ERROR_CONTAINS_IMPL(sceneParseError(R"({"render": {"msaa": 2.5}})"),
                                  "scene.json: /render/msaa: expected an integer in [0, 4294967295], got number 2.5");
  EXPECT_THAT_ERROR_CONTAINS_IMPL(sceneParseError(R"({"render": {"width": -3}})"), "/render/width: expected an integer");
  EXPECT_THAT_ERROR_CONTAINS_IMPL(sceneParseError(R"({"light": {"direction": [0, "up", 0]}})"),
                                  "scene.json: /light/direction/1: expected a number, got string");
  EXPECT_THAT_ERROR_CONTAINS_IMPL(sceneParseError(R"({"camera": {"target": [0, 1]}})"),
                                  "scene.json: /camera/target: expected an array of 3 numbers, got array");
  EXPECT_THAT_ERROR_CONTAINS_IMPL(sceneParseError(R"({"material": 3})"), "scene.json: /material: expected an object, got number");
  EXPECT_THAT_ERROR_CONTAINS_IMPL(sceneParseError(R"({"model": {"keepStrands": "yes"}})"),
                                  "scene.json: /model/keepStrands: expected true or false, got string");
  EXPECT_THAT_ERROR_CONTAINS_IMPL(sceneParseError(R"({"colliders": {"radius": 1}})"),
                                  "scene.json: /colliders: expected an array, got object");
  EXPECT_THAT_ERROR_CONTAINS_IMPL(sceneParseError("[1, 2]"), "scene.json: /: expected an object, got array");
}

TEST(Scene, UnknownKeysAreErrors) {
  EXPECT_THAT_ERROR_CONTAINS_IMPL(sceneParseError(R"({"simulaton": {}})"), "scene.json: /simulaton: unknown key");
  EXPECT_THAT_ERROR_CONTAINS_IMPL(sceneParseError(R"({"simulation": {"dampnig": 0.1}})"),
                                  "scene.json: /simulation/dampnig: unknown key");
  EXPECT_THAT_ERROR_CONTAINS_IMPL(sceneParseError(R"({"colliders": [{"center": [0,0,0], "radius": 1, "r": 2}]})"),
                                  "scene.json: /colliders/0/r: unknown key");
}

TEST(Scene, OutOfRangeValuesNameThePath) {
  EXPECT_THAT_ERROR_CONTAINS_IMPL(sceneParseError(R"({"render": {"msaa": 3}})"),
                                  "scene.json: /render/msaa: must be 1, 2, 4 or 8, got 3");
  EXPECT_THAT_ERROR_CONTAINS_IMPL(sceneParseError(R"({"render": {"width": 0}})"), "/render/width: must be in [1, 16384]");
  EXPECT_THAT_ERROR_CONTAINS_IMPL(sceneParseError(R"({"render": {"raster": "cuda"}})"),
                                  "/render/raster: raster must be auto, compute or graphics, got 'cuda'");
  EXPECT_THAT_ERROR_CONTAINS_IMPL(sceneParseError(R"({"camera": {"fovDeg": 180}})"), "/camera/fovDeg: must be in (0, 180)");
  EXPECT_THAT_ERROR_CONTAINS_IMPL(sceneParseError(R"({"camera": {"distance": 0}})"), "/camera/distance: must be in (0, 10000]");
  // Finite but past head space: their lengths overflow (the messages named a zero vector or the view's matrices).
  EXPECT_THAT_ERROR_CONTAINS_IMPL(sceneParseError(R"({"camera": {"distance": 1e30}})"), "/camera/distance: must be in (0, 10000]");
  EXPECT_THAT_ERROR_CONTAINS_IMPL(sceneParseError(R"({"light": {"direction": [1e30, 1e30, 1e30]}})"),
                                  "/light/direction: components must be within +-10000");
  EXPECT_THAT_ERROR_CONTAINS_IMPL(sceneParseError(R"({"light": {"type": "spot", "position": [1e30, 0, 0]}})"),
                                  "/light/position: components must be within +-10000");
  EXPECT_THAT_ERROR_CONTAINS_IMPL(sceneParseError(R"({"light": {"direction": [0, 0, 0]}})"),
                                  "/light/direction: must be a non-zero vector");
  EXPECT_THAT_ERROR_CONTAINS_IMPL(sceneParseError(R"({"light": {"intensity": -1}})"), "/light/intensity: must be >= 0");
  EXPECT_THAT_ERROR_CONTAINS_IMPL(sceneParseError(R"({"colliders": [{"center": [0, 0, 0], "radius": -1}]})"),
                                  "/colliders/0/radius: must be > 0");
  EXPECT_THAT_ERROR_CONTAINS_IMPL(sceneParseError(R"({"colliders": [{"center": [0, 0, 0]}]})"),
                                  "/colliders/0/radius: is required");
  EXPECT_THAT_ERROR_CONTAINS_IMPL(sceneParseError(R"({"growth": {"particles": 80}})"),
                                  "scene.json: /growth: growth options: particles per guide must be in [2, 64], got 80");
  EXPECT_THAT_ERROR_CONTAINS_IMPL(sceneParseError(R"({"density": {"strandsPerTriangle": 4, "totalStrands": 9}})"),
                                  "/density/totalStrands: give either strandsPerTriangle or totalStrands, not both");
  EXPECT_THAT_ERROR_CONTAINS_IMPL(sceneParseError(R"({"model": {"source": "head.fbx"}})"),
                                  "/model/source: expected \"default\" or a path ending in .hair, .tfx or .obj, got \"head.fbx\"");
  EXPECT_THAT_ERROR_CONTAINS_IMPL(sceneParseError(R"({"model": {"up": "x"}})"), "/model/up: expected \"y\" or \"z\", got \"x\"");
  EXPECT_THAT_ERROR_CONTAINS_IMPL(sceneParseError(R"({"model": {"scale": 0}})"), "/model: model transform: scale must be positive");
  EXPECT_THAT_ERROR_CONTAINS_IMPL(sceneParseError(R"({"simulation": {"iterations": 0}})"),
                                  "scene.json: /simulation: simulation parameter iterations must be in [1, 1000], got 0");
  EXPECT_THAT_ERROR_CONTAINS_IMPL(sceneParseError(R"({"material": {"eta": -1}})"), "scene.json: /material: ");
  EXPECT_THAT_ERROR_CONTAINS_IMPL(sceneParseError(R"({"groom": {"curlRadius": 2}})"),
                                  "scene.json: /groom: GroomSettings.curlRadius must be in [0, 1], got 2");
  EXPECT_THAT_ERROR_CONTAINS_IMPL(sceneParseError(R"({"groom": {"curl": 1}})"), "scene.json: /groom/curl: unknown key");
}

TEST(Scene, ReadsTheGroom) {
  const Scene s = parseScene(R"({"groom": {"clumpsPerTriangle": 2, "clumpStrength": 0.7, "curlRadius": 0.006,
                                  "curlTurns": 40, "frizzAmplitude": 0.002, "frizzHairline": 2.5,
                                  "frizzHairlineWidth": 0.03}})", "scene.json", "/base");
  EXPECT_EQ(s.groom.clumpsPerTriangle, 2u);
  EXPECT_FLOAT_EQ(s.groom.clumpStrength, 0.7f);
  EXPECT_FLOAT_EQ(s.groom.curlRadius, 0.006f);
  EXPECT_FLOAT_EQ(s.groom.curlTurns, 40.0f);
  EXPECT_FLOAT_EQ(s.groom.frizzAmplitude, 0.002f);
  EXPECT_FLOAT_EQ(s.groom.frizzFrequency, GroomSettings{}.frizzFrequency);
  EXPECT_FLOAT_EQ(s.groom.frizzHairline, 2.5f);
  EXPECT_FLOAT_EQ(s.groom.frizzHairlineWidth, 0.03f);
}

TEST(Scene, LoadsFromAFileAndResolvesPathsAgainstIt) {
  test::TempDir dir;
  test::writeText(dir / "s.json", R"({"model": {"source": "m.hair"}})");
  Scene s = loadSceneFile(dir / "s.json");
  EXPECT_EQ(s.model.path, dir / "m.hair");
  EXPECT_EQ(s.source, (dir / "s.json").string());
  EXPECT_ERROR_CONTAINS(loadSceneFile(dir / "missing.json"), "missing.json: cannot open");
}

TEST(SceneAsset, BuildsTheDefaultHeadWithOverrides) {
  Scene s = parseSceneText(R"({"density": {"totalStrands": 1000}, "colliders": [{"center": [0, 0, 0], "radius": 0.1}]})");
  HairAsset a = buildSceneAsset(s);
  EXPECT_EQ(a.name, "default head");
  EXPECT_EQ(a.topology.strands.size(), 1000u);
  ASSERT_EQ(a.colliders.size(), 1u);
}

TEST(SceneAsset, BuildsFromAHairModelInCentimetresZUp) {
  test::TempDir dir;
  SyntheticHairOptions o;
  o.strands = 400;
  o.points = 400 * 20;
  o.radius = 10.0f;  // centimetres
  o.length = 30.0f;
  HairFileData d = makeSyntheticHair(o);
  for (auto& p : d.points) p = glm::vec3(p.x, -p.z, p.y);  // store it Z-up
  writeHairFile(dir / "m.hair", d);
  test::writeText(dir / "s.json", R"({"model": {"source": "m.hair", "scale": 0.01, "up": "z"},
                                      "growth": {"particles": 8}, "density": {"strandsPerTriangle": 2}})");
  HairAsset a = buildSceneAsset(loadSceneFile(dir / "s.json"));
  EXPECT_EQ(a.guides.guideCount(), 400u);
  EXPECT_EQ(a.guides.particlesPerGuide, 8u);
  ASSERT_EQ(a.colliders.size(), 1u);
  EXPECT_NEAR(a.colliders[0].radius, 0.1f, 1e-3f);  // fitted to the roots, in metres
  EXPECT_NEAR(glm::length(a.colliders[0].center), 0.0f, 1e-3f);
  EXPECT_GT(a.guides.root(0).y, 0.0f);  // roots on the upper cap again after Z-up -> Y-up
  EXPECT_EQ(a.topology.strands.size(), 2 * a.topology.triangles.size());
  EXPECT_TRUE(a.fittedCollider);  // a sphere fitted to the roots only collides: no head is drawn
  EXPECT_TRUE(a.head.indices.empty());
}

TEST(SceneAsset, BuildsFromAnObjScalp) {
  test::TempDir dir;
  std::filesystem::copy_file(std::filesystem::path(HAIRPIPE_TEST_DATA_DIR) / "scalp_cap.obj", dir / "cap.obj");
  test::writeText(dir / "s.json", R"({"model": "cap.obj", "growth": {"length": 1.0}})");
  HairAsset a = buildSceneAsset(loadSceneFile(dir / "s.json"));
  EXPECT_EQ(a.guides.guideCount(), 49u);
  // The guides hang down every side of the cap; the pole's own guide falls to one side, so 9 of the 12
  // triangles around the pole blend it with guides falling the other way, through the head: dropped.
  std::uint32_t poleKept = 0;
  for (const auto& t : a.topology.triangles) poleKept += t.x == 0 || t.y == 0 || t.z == 0;
  EXPECT_EQ(a.partedTriangles, 9u);
  EXPECT_EQ(poleKept, 12u - a.partedTriangles);
  EXPECT_EQ(a.topology.triangles.size() + a.partedTriangles, 84u);
  ASSERT_EQ(a.colliders.size(), 1u);
  EXPECT_NEAR(a.colliders[0].radius, 1.0f, 1e-3f);
}

TEST(SceneAsset, MissingModelFileIsAnError) {
  test::TempDir dir;
  test::writeText(dir / "s.json", R"({"model": "nope.hair"})");
  EXPECT_ERROR_CONTAINS(buildSceneAsset(loadSceneFile(dir / "s.json")), "nope.hair: cannot open");
}

TEST(SceneSimParams, DefaultsAreValidAndBadFieldsAreNamed) {
  EXPECT_NO_THROW(SimulationParams{}.validate());
  SimulationParams p;
  p.dt = 0.0;
  EXPECT_ERROR_CONTAINS(p.validate(), "simulation parameter dt must be in (0, 1] seconds");
  p = {};
  p.damping = NAN;
  EXPECT_ERROR_CONTAINS(p.validate(), "simulation parameter damping must be in [0, 1], got NaN");
  p = {};
  p.iterations = 1001;
  EXPECT_ERROR_CONTAINS(p.validate(), "iterations must be in [1, 1000]");
  p = {};
  p.pearlRadius = -0.1;
  EXPECT_ERROR_CONTAINS(p.validate(), "pearlRadius must be in [0, 1000]");
  // Finite but absurd: each of these turned every particle into NaN within a frame, the run exiting 0.
  p = {};
  p.pearlRadius = 1e20;
  EXPECT_ERROR_CONTAINS(p.validate(), "pearlRadius must be in [0, 1000]");
  p = {};
  p.gravity = glm::dvec3(1e38);
  EXPECT_ERROR_CONTAINS(p.validate(), "gravity must be at most 100000 long");
  p = {};
  p.windDirection = glm::dvec3(1.0, 0.0, 0.0);
  p.windStrength = 1e30;
  EXPECT_ERROR_CONTAINS(p.validate(), "windStrength must be in [0, 100000]");
  p = {};
  p.maxSpeed = 1e30;
  EXPECT_ERROR_CONTAINS(p.validate(), "maxSpeed must be in (0, 1000000], got 1e+30");
  p = {};
  p.localStiffness = 0.95;  // local shape overshoots near 1 (docs/THEORY.md §2.6)
  EXPECT_ERROR_CONTAINS(p.validate(), "simulation parameter localStiffness must be in [0, 0.9], got 0.95");
  p = {};
  p.gravity.y = INFINITY;
  EXPECT_ERROR_CONTAINS(p.validate(), "gravity must be finite (component 1), got Inf");
  p = {};
  p.windStrength = 1.0;
  p.windDirection = glm::dvec3(0.0);
  EXPECT_ERROR_CONTAINS(p.validate(), "windDirection must be non-zero when windStrength > 0");
  p = {};
  p.maxSpeed = 0.0;
  EXPECT_ERROR_CONTAINS(p.validate(), "maxSpeed must be in (0, ");
  p = {};
  p.substeps = 0;
  EXPECT_ERROR_CONTAINS(p.validate(), "substeps must be in [1, 64]");
}
}  // namespace
}  // namespace hp

namespace hp {
namespace {
// The schema example in engine/core/hair/README.md must stay a valid scene with the documented defaults.
TEST(SceneReadme, ExampleParsesAndMatchesTheDefaults) {
  std::ifstream in(std::filesystem::path(HAIRPIPE_TEST_DATA_DIR) / "../../engine/core/hair/README.md");
  ASSERT_TRUE(in) << "engine/core/hair/README.md not found";
  std::string text((std::istreambuf_iterator<char>(in)), {});
  auto begin = text.find("```json\n"), end = text.find("```", begin + 8);
  ASSERT_NE(begin, std::string::npos);
  std::string json, line;
  std::istringstream lines(text.substr(begin + 8, end - begin - 8));
  while (std::getline(lines, line)) json += line.substr(0, line.find("//")) + "\n";  // drop the comments
  Scene s = parseScene(json, "README.md", "/base");
  Scene d;
  EXPECT_EQ(s.growth, d.growth);
  EXPECT_EQ(s.density, d.density);
  EXPECT_EQ(s.model.kind, ModelSpec::Kind::Default);
  EXPECT_NEAR(s.material.alphaR, d.material.alphaR, 1e-12);
  EXPECT_NEAR(s.simulation.dt, d.simulation.dt, 1e-6);
  EXPECT_EQ(s.simulation.iterations, d.simulation.iterations);
  EXPECT_EQ(s.render.width, d.render.width);
  EXPECT_EQ(s.camera.distance, d.camera.distance);
  ASSERT_EQ(s.lights.size(), d.lights.size());
  EXPECT_NEAR(glm::distance(s.lights[0].direction, d.lights[0].direction), 0.0f, 1e-6f);
  EXPECT_EQ(s.groom, d.groom);
}
}  // namespace
}  // namespace hp
