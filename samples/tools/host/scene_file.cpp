// Scene file parsing: one function per section, each reading its keys and checking its ranges.
#include <cmath>

#include "engine/core/error.h"
#include "engine/core/number_text.h"
#include "engine/core/hair/default_head.h"
#include "engine/core/hair/input_file.h"
#include "engine/core/hair/mesh_file.h"
#include "samples/tools/host/json_reader.h"
#include "engine/core/hair/scene.h"
#include "samples/tools/host/scene_file.h"

namespace hp {
namespace {
// Runs a struct's own validate() and prefixes its message with the section's location.
template <typename T>
void validateSection(const T& value, const JsonObject& section, const std::string& pointer) {
  try {
    value.validate();
  } catch (const Error& e) {
    throw Error(section.where(pointer) + ": " + e.what());
  }
}

void requireThat(bool ok, JsonObject& o, const char* key, const std::string& message) {
  if (!ok) o.fail(key, message);
}

ModelSpec::Kind kindOf(const std::string& source, JsonObject& o) {
  if (source == "default") return ModelSpec::Kind::Default;
  if (const std::optional<ModelSpec::Kind> kind = modelKindOf(source)) return *kind;
  o.fail("source", "expected \"default\" or a path ending in .hair, .tfx or .obj, got \"" + excerpt(source) + "\"");
}

void readModel(JsonObject& root, ModelSpec& model, const std::filesystem::path& baseDir) {
  const nlohmann::json* v = root.value("model");
  if (!v) return;
  nlohmann::json object = v->is_string() ? nlohmann::json{{"source", *v}} : *v;  // "model": "x.hair"
  JsonObject o(object, root.pointer("model"), root.file());
  std::string source = "default", up = upAxisName(model.transform.up);
  o.read("source", source);
  o.read("scale", model.transform.scale);
  o.read("up", up);
  o.read("translate", model.transform.translation);
  o.read("keepStrands", model.keepStrands);
  o.finish();
  model.kind = kindOf(source, o);
  if (model.kind != ModelSpec::Kind::Default) model.path = baseDir / source;
  requireThat(up == "y" || up == "z" || up == "Y" || up == "Z", o, "up", "expected \"y\" or \"z\", got \"" + excerpt(up) + "\"");
  model.transform.up = parseUpAxis(up);
  validateSection(model.transform, o, root.pointer("model"));
}

void readGrowth(JsonObject& root, GrowthOptions& g) {
  auto o = root.object("growth");
  if (!o) return;
  o->read("particles", g.particlesPerGuide);
  o->read("length", g.length);
  o->read("lengthVariation", g.lengthVariation);
  o->read("segmentRatio", g.segmentRatio);
  o->read("bend", g.bend);
  o->read("bendDirection", g.bendDirection);
  o->read("seed", g.seed);
  o->finish();
  validateSection(g, *o, root.pointer("growth"));
}

void readDensity(JsonObject& root, DensityOptions& d) {
  auto o = root.object("density");
  if (!o) return;
  if (o->has("strandsPerTriangle") && o->has("totalStrands"))
    o->fail("totalStrands", "give either strandsPerTriangle or totalStrands, not both");
  if (o->has("strandsPerTriangle")) d.mode = DensityOptions::Mode::PerTriangle;
  if (o->has("totalStrands")) d.mode = DensityOptions::Mode::Total;
  bool own = false;
  o->read("ownStrands", own);
  if (own && (o->has("strandsPerTriangle") || o->has("totalStrands")))
    o->fail("ownStrands", "draws the model's own strands: give no strand count with it");
  if (own) d.mode = DensityOptions::Mode::Guides;
  o->read("strandsPerTriangle", d.strandsPerTriangle);
  o->read("totalStrands", d.totalStrands);
  o->read("seed", d.seed);
  o->finish();
  validateSection(d, *o, root.pointer("density"));
}

// Each entry is a sphere {"center", "radius"} or a closed OBJ mesh {"mesh", "cell"} (head space,
// scene units; cell: the distance grid's spacing, default: 1/64 of the mesh's longest side).
void readColliders(JsonObject& root, Scene& scene, const std::filesystem::path& baseDir) {
  const nlohmann::json* list = root.array("colliders");
  if (!list) return;
  scene.colliders.emplace();
  for (std::size_t i = 0; i < list->size(); ++i) {
    JsonObject c((*list)[i], root.pointer("colliders") + "/" + std::to_string(i), root.file());
    if (c.has("mesh")) {
      MeshColliderSpec m;
      std::string path;
      c.read("mesh", path);
      c.read("cell", m.cell);
      c.finish();
      requireThat(!path.empty(), c, "mesh", "must name an .obj file");
      requireThat(std::isfinite(m.cell) && m.cell >= 0.0f, c, "cell", "must be > 0 (or 0: automatic)");
      m.path = baseDir / path;
      scene.colliderMeshes.push_back(m);
      continue;
    }
    SphereCollider s;
    if (!c.has("center") || !c.has("radius")) c.fail(c.has("center") ? "radius" : "center", "is required (or \"mesh\")");
    c.read("center", s.center);
    c.read("radius", s.radius);
    c.finish();
    requireThat(std::isfinite(s.radius) && s.radius > 0.0f, c, "radius", "must be > 0");
    scene.colliders->push_back(s);
  }
}

// "mesh": "body.glb" or {"source": "body.glb", "cell": 0.004}: the character mesh (in the model's units and axes).
void readCharacterMesh(JsonObject& root, Scene& scene, const std::filesystem::path& baseDir) {
  const nlohmann::json* v = root.value("mesh");
  if (!v) return;
  nlohmann::json object = v->is_string() ? nlohmann::json{{"source", *v}} : *v;
  JsonObject o(object, root.pointer("mesh"), root.file());
  CharacterMeshSpec m;
  std::string source;
  o.read("source", source);
  o.read("cell", m.cell);
  o.finish();
  requireThat(meshKindOf(source).has_value(), o, "source", "must name an .obj, .ply, .gltf, .glb or .tfxmesh file, got \"" + excerpt(source) + "\"");
  requireThat(std::isfinite(m.cell) && m.cell >= 0.0f, o, "cell", "must be > 0 (or 0: automatic)");
  m.path = baseDir / source;
  scene.mesh = m;
}

void readMaterial(JsonObject& root, HairMaterial& m) {
  auto o = root.object("material");
  if (!o) return;
  o->read("eta", m.eta);
  o->read("absorption", m.absorption);
  o->readDegrees("alphaRDeg", m.alphaR);
  o->readDegrees("betaRDeg", m.betaR);
  o->read("kG", m.kG);
  o->readDegrees("wcDeg", m.wc);
  o->read("dEta", m.dEta);
  o->read("dhM", m.dhM);
  o->readDegrees("betaNDeg", m.betaN);
  o->readDegrees("tiltVariationDeg", m.tiltVariation);
  o->read("roughnessVariation", m.roughnessVariation);
  o->finish();
  validateSection(m, *o, root.pointer("material"));
}

LightSpec::Type lightTypeOf(JsonObject& o) {
  std::string type = "directional";
  o.read("type", type);
  if (type == "directional") return LightSpec::Type::Directional;
  if (type == "spot") return LightSpec::Type::Spot;
  if (type == "point") return LightSpec::Type::Point;
  o.fail("type", "expected \"directional\", \"spot\" or \"point\", got \"" + excerpt(type) + "\"");
}

// A key of another light type is refused rather than ignored: a forgotten "type" would otherwise pass.
void refuseForeignKeys(JsonObject& o, LightSpec::Type type) {
  const bool spot = type == LightSpec::Type::Spot, point = type == LightSpec::Type::Point;
  for (const char* key : {"position", "range"})
    requireThat(spot || point || !o.has(key), o, key, "is for a spot or point light only (\"type\": \"spot\" or \"point\")");
  for (const char* key : {"target", "coneDeg"})
    requireThat(spot || !o.has(key), o, key, "is for a spot light only (\"type\": \"spot\")");
  requireThat(!spot || !o.has("direction"), o, "direction", "a spot light aims with \"target\", not \"direction\"");
  requireThat(!point || !o.has("direction"), o, "direction", "a point light shines every way from \"position\": no \"direction\"");
  requireThat(!(spot || point) || o.has("position"), o, "position",
              std::string("is required for a ") + lightTypeName(type) + " light");
}

// One light object ("light", or an entry of "lights" at `pointer`): "type" directional (default) reads
// direction; spot reads position (required), target, coneDeg and range; point reads position (required)
// and range; every type reads color, intensity and shadows.
LightSpec readLightObject(JsonObject& o, const std::string& pointer) {
  LightSpec l;
  l.type = lightTypeOf(o);
  refuseForeignKeys(o, l.type);
  glm::vec3 target{0.0f};
  o.read("direction", l.direction);
  o.read("position", l.position);
  o.read("target", target);
  // Past head space's extent a length overflows (a direction of 1e30s read as a zero vector).
  requireThat(withinHeadSpace(l.direction), o, "direction", headSpaceRule());
  requireThat(withinHeadSpace(l.position), o, "position", headSpaceRule());
  requireThat(withinHeadSpace(target), o, "target", headSpaceRule());
  o.read("coneDeg", l.coneDeg);
  o.read("range", l.range);
  o.read("color", l.color);
  o.read("intensity", l.intensity);
  o.read("shadows", l.shadows);
  o.finish();
  if (l.type == LightSpec::Type::Spot) {
    l.direction = l.position - target;
    requireThat(glm::length(l.direction) > 1e-6f, o, "target", "must differ from position");
  }
  float len = glm::length(l.direction);
  requireThat(std::isfinite(len) && len > 1e-6f, o, "direction", "must be a non-zero vector");
  l.direction /= len;
  requireThat(glm::all(glm::greaterThanEqual(l.color, glm::vec3(0.0f))), o, "color", "components must be >= 0");
  requireThat(std::isfinite(l.intensity) && l.intensity >= 0.0f, o, "intensity", "must be >= 0");
  requireThat(l.coneDeg > 0.0f && l.coneDeg <= 80.0f, o, "coneDeg", "must be in (0, 80], got " + hp::numberText(l.coneDeg));
  requireThat(std::isfinite(l.range) && l.range >= 0.0f, o, "range", "must be >= 0 (0: no distance falloff)");
  validateSection(l, o, pointer);
  return l;
}

// "light" (one light) or "lights" (a list of up to kMaxSceneLights, possibly empty), not both; either
// replaces the default sun.
void readLights(JsonObject& root, std::vector<LightSpec>& lights) {
  if (root.has("light") && root.has("lights"))
    root.fail("lights", "give either \"light\" (one light) or \"lights\" (a list), not both");
  if (auto o = root.object("light")) {
    lights = {readLightObject(*o, root.pointer("light"))};
    return;
  }
  const nlohmann::json* list = root.array("lights");
  if (!list) return;
  if (list->size() > kMaxSceneLights)
    root.fail("lights", "at most " + std::to_string(kMaxSceneLights) + " lights, got " + std::to_string(list->size()));
  lights.clear();
  for (std::size_t i = 0; i < list->size(); ++i) {
    const std::string pointer = root.pointer("lights") + "/" + std::to_string(i);
    JsonObject o((*list)[i], pointer, root.file());
    lights.push_back(readLightObject(o, pointer));
  }
}

void readCamera(JsonObject& root, CameraSpec& c) {
  auto o = root.object("camera");
  if (!o) return;
  o->read("orbitDeg", c.orbitDeg);
  o->read("elevationDeg", c.elevationDeg);
  o->read("distance", c.distance);
  o->read("fovDeg", c.fovDeg);
  o->read("target", c.target);
  o->finish();
  requireThat(std::abs(c.elevationDeg) <= 89.0f, *o, "elevationDeg", "must be in [-89, 89]");
  requireThat(c.distance > 0.0f && c.distance <= kMaxHeadSpaceCoordinate, *o, "distance",
              "must be in (0, " + std::to_string(int(kMaxHeadSpaceCoordinate)) + "]");
  requireThat(withinHeadSpace(c.target), *o, "target", headSpaceRule());
  requireThat(c.fovDeg > 0.0f && c.fovDeg < 180.0f, *o, "fovDeg", "must be in (0, 180)");
}

void readRender(JsonObject& root, RenderSpec& r) {
  auto o = root.object("render");
  if (!o) return;
  o->read("width", r.width);
  o->read("height", r.height);
  o->read("msaa", r.msaa);
  std::string raster = rasterModeName(r.raster);
  o->read("raster", raster);
  o->finish();
  try {
    r.raster = parseRasterMode(raster);
  } catch (const Error& e) {
    requireThat(false, *o, "raster", e.what());
  }
  requireThat(r.width >= 1 && r.width <= 16384, *o, "width", "must be in [1, 16384], got " + std::to_string(r.width));
  requireThat(r.height >= 1 && r.height <= 16384, *o, "height", "must be in [1, 16384], got " + std::to_string(r.height));
  requireThat(r.msaa == 1 || r.msaa == 2 || r.msaa == 4 || r.msaa == 8, *o, "msaa",
              "must be 1, 2, 4 or 8, got " + std::to_string(r.msaa));
}

void readSimulation(JsonObject& root, SimulationParams& s) {
  auto o = root.object("simulation");
  if (!o) return;
  o->read("dt", s.dt);
  o->read("substeps", s.substeps);
  o->read("iterations", s.iterations);
  o->read("gravity", s.gravity);
  o->read("damping", s.damping);
  o->read("pearlRadius", s.pearlRadius);
  o->read("stiffness", s.stiffness);
  o->read("stiffnessFalloff", s.stiffnessFalloff);
  o->read("localStiffness", s.localStiffness);
  o->read("maxSpeed", s.maxSpeed);
  o->read("volume", s.volume);
  o->read("volumeTarget", s.volumeTarget);
  o->read("friction", s.friction);
  o->read("gridResolution", s.gridResolution);
  o->read("windDirection", s.windDirection);
  o->read("windStrength", s.windStrength);
  o->read("windGust", s.windGust);
  o->read("windGustFrequency", s.windGustFrequency);
  o->finish();
  validateSection(s, *o, root.pointer("simulation"));
}
void readGroom(JsonObject& root, GroomSettings& g) {
  auto o = root.object("groom");
  if (!o) return;
  o->read("clumpsPerTriangle", g.clumpsPerTriangle);
  o->read("clumpStrength", g.clumpStrength);
  o->read("clumpShape", g.clumpShape);
  o->read("curlRadius", g.curlRadius);
  o->read("curlTurns", g.curlTurns);
  o->read("curlVariation", g.curlVariation);
  o->read("frizzAmplitude", g.frizzAmplitude);
  o->read("frizzFrequency", g.frizzFrequency);
  o->read("frizzHairline", g.frizzHairline);
  o->read("frizzHairlineWidth", g.frizzHairlineWidth);
  o->finish();
  validateSection(g, *o, root.pointer("groom"));
}
}  // namespace

Scene parseScene(const std::string& jsonText, const std::string& source, const std::filesystem::path& baseDir) {
  nlohmann::json json = parseJsonText(jsonText, source);
  JsonObject root(json, "", source);
  Scene scene;
  scene.source = source;
  readModel(root, scene.model, baseDir);
  readGrowth(root, scene.growth);
  readDensity(root, scene.density);
  readColliders(root, scene, baseDir);
  readCharacterMesh(root, scene, baseDir);
  readMaterial(root, scene.material);
  readLights(root, scene.lights);
  readCamera(root, scene.camera);
  readRender(root, scene.render);
  readSimulation(root, scene.simulation);
  readGroom(root, scene.groom);
  root.finish();
  return scene;
}

Scene loadSceneFile(const std::filesystem::path& path) {
  return parseScene(readInputText(path, kMaxTextFileBytes), path.string(), path.parent_path());
}
}  // namespace hp
