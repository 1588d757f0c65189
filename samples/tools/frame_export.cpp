#include "samples/tools/frame_export.h"

#include <cmath>

#include <nlohmann/json.hpp>

#include "engine/core/error.h"
#include "engine/core/hair/atomic_write.h"
#include "engine/core/hair/input_file.h"
#include "engine/core/shading/lut.h"
#include "samples/tools/environment_file.h"
#include "samples/tools/host/json_reader.h"
#include "samples/tools/linear_image.h"
#include "samples/tools/obj_albedo_mesh.h"
#include "samples/tools/reference/fibre.h"
#include "samples/tools/render_targets.h"
#include "shaders/shared/strands.h"
#include "samples/tools/host/json_text.h"

namespace hp {
namespace {
constexpr const char* kFormat = "hairpipe-frame";
// 5: "fibre"/"strand_roughness_scales" and the material's "roughness_variation"; 4: "fibre"/"strand_tilts_rad"
// and the material's "tilt_variation_rad"; 3: an optional "environment_map"; 2: "lights", a list (point lights,
// shadows); 1: one "light". All are read.
constexpr std::uint32_t kVersion = 5;

nlohmann::json vec(const glm::vec3& v) { return {v.x, v.y, v.z}; }
nlohmann::json dvec(const glm::dvec3& v) { return {v.x, v.y, v.z}; }

// The strands as drawn: Q points each, width = root width x strand scale x mix(1, tip, along)
// (shaders/strands.vert), colour = the hair albedo x the strand's lightness scale.
HairFileData exportStrands(const FrameCapture& f, const render::LookSettings& look, const glm::vec3& albedo) {
  const std::uint32_t q = f.verticesPerStrand;
  const std::uint32_t strands = std::uint32_t(f.strands.attributes.size());
  if (q < 2 || f.strands.positions.size() != std::size_t(strands) * q) throw Error("frame export: inconsistent strand capture");
  HairFileData hair;
  hair.strandCount = strands;
  hair.defaultSegments = q - 1;
  hair.setInfoText("hairpipe frame export: render strands as drawn");
  for (std::uint32_t s = 0; s < strands; ++s) {
    const auto& a = f.strands.attributes[s];
    for (std::uint32_t j = 0; j < q; ++j) {
      const glm::vec4 p = f.strands.positions[std::size_t(s) * q + j];
      hair.points.emplace_back(p);
      hair.thickness.push_back(look.strandWidth * a.widthScale * (1.0f + (look.tipWidthFraction - 1.0f) * p.w));
      hair.colors.push_back(albedo * a.colorScale);
    }
  }
  return hair;
}

void exportHead(ExportedFrame& out, const HeadMesh& head, const glm::mat4& headToWorld) {
  const glm::mat3 linear(headToWorld);
  const glm::vec3 hairUnderScalp = 0.5f * out.hairAlbedo;
  for (std::size_t i = 0; i < head.positions.size(); ++i) {
    out.headPositions.push_back(glm::vec3(headToWorld * glm::vec4(head.positions[i], 1.0f)));
    out.headNormals.push_back(glm::normalize(linear * head.normals[i]));
    const float scalp = head.scalp.empty() ? 0.0f : head.scalp[i];
    out.headAlbedo.push_back(glm::mix(out.skinColor, hairUnderScalp, scalp));  // shaders/head.frag
  }
  out.headIndices = head.indices;
}

nlohmann::json lightJson(const LightSpec& l) {
  return {{"type", lightTypeName(l.type)},
          {"direction", vec(l.direction)}, {"color", vec(l.color)}, {"intensity", l.intensity},
          {"irradiance", vec(l.color * l.intensity)}, {"position", vec(l.position)},
          {"cone_deg", l.coneDeg}, {"range", l.range}, {"shadows", l.shadows}};
}

nlohmann::json lightsJson(const std::vector<LightSpec>& lights) {
  nlohmann::json list = nlohmann::json::array();
  for (const LightSpec& l : lights) list.push_back(lightJson(l));
  return list;
}

nlohmann::json materialJson(const HairMaterial& m) {
  return {{"eta", m.eta}, {"absorption", dvec(m.absorption)}, {"alpha_r_rad", m.alphaR}, {"beta_r_rad", m.betaR},
          {"kg", m.kG}, {"wc_rad", m.wc}, {"deta", m.dEta}, {"dhm", m.dhM}, {"beta_n_rad", m.betaN},
          {"tilt_variation_rad", m.tiltVariation}, {"roughness_variation", m.roughnessVariation}};
}

nlohmann::json frameJson(const ExportedFrame& f) {
  const auto& c = f.camera;
  nlohmann::json j = {{"format", kFormat}, {"version", kVersion}, {"units", "metres"}, {"up", "+y"},
          {"files", {{"strands", FrameExportFiles::strands}, {"head", FrameExportFiles::head}}},
          {"camera", {{"position", vec(c.position)}, {"target", vec(c.target)}, {"up", vec(c.up)},
                      {"fov_y_deg", c.fovYDeg}, {"width", c.width}, {"height", c.height}}},
          {"lights", lightsJson(f.lights)},
          {"fibre", {{"model", f.fibreModel}, {"lut_mode", f.lutMode}, {"material", materialJson(f.material)},
                     {"albedo", vec(f.hairAlbedo)}, {"strand_tilts_rad", f.strandTilts},
                     {"strand_roughness_scales", f.strandRoughness}}},
          {"skin", {{"color", vec(f.skinColor)}, {"wrap", f.wrap}}},
          {"environment_radiance", f.environment}, {"background_radiance", vec(f.background)},
          {"exposure", f.exposure}, {"tonemap", "filmic (shaders/shared/tonemap.h) then sRGB"}};
  if (f.environmentMap)
    j["environment_map"] = {{"file", FrameExportFiles::environment}, {"intensity", f.environmentMap->intensity},
                            {"rotation_deg", f.environmentMap->rotationDeg}};
  return j;
}

// The environment map's texels as a PFM (intensity and rotation stay in frame.json).
LinearImage environmentImage(const EnvironmentMap& map) {
  LinearImage image(map.width, map.height, 3);
  for (std::size_t i = 0; i < map.texels.size(); ++i)
    for (int c = 0; c < 3; ++c) image.values[3 * i + c] = map.texels[i][c];
  return image;
}

// "environment_map" of frame.json, with its image from the export folder.
std::shared_ptr<const EnvironmentMap> readEnvironmentMap(JsonObject o, const std::filesystem::path& dir) {
  std::string file;
  double intensity = 1.0, rotationDeg = 0.0;
  o.read("file", file);
  o.read("intensity", intensity);
  o.read("rotation_deg", rotationDeg);
  o.finish();
  if (file != FrameExportFiles::environment) o.fail("file", "expected \"environment.pfm\"");
  try {
    auto map = std::make_shared<EnvironmentMap>(readEnvironmentFile(dir / file));
    map->intensity = intensity;
    map->rotationDeg = rotationDeg;
    map->validate();
    return map;
  } catch (const Error& e) {
    o.fail("file", e.what());
  }
}

// One light at `pointer`; "shadows" is absent from version 1 (every light cast shadows then).
LightSpec readLight(JsonObject o, const std::string& pointer) {
  LightSpec l;
  std::string type;
  o.read("type", type);
  if (type == "spot") l.type = LightSpec::Type::Spot;
  else if (type == "point") l.type = LightSpec::Type::Point;
  else if (type != "directional") o.fail("type", "expected \"directional\", \"spot\" or \"point\"");
  o.read("direction", l.direction);
  o.read("color", l.color);
  o.read("intensity", l.intensity);
  o.value("irradiance");  // derived (colour x intensity), informative only
  o.read("position", l.position);
  o.read("cone_deg", l.coneDeg);
  o.read("range", l.range);
  o.read("shadows", l.shadows);
  o.finish();
  try {
    l.validate();
  } catch (const Error& e) {
    throw Error(o.where(pointer) + ": " + e.what());
  }
  return l;
}

// Every channel finite and in [0, 1] (NaN fails the comparisons).
bool inUnitRange(const glm::vec3& v) {
  return v.x >= 0.0f && v.y >= 0.0f && v.z >= 0.0f && v.x <= 1.0f && v.y <= 1.0f && v.z <= 1.0f;
}

// Before version 4 the strands shared one alpha_R, before 5 one beta_R: no variation unless the file says one.
HairMaterial readMaterial(JsonObject o) {
  HairMaterial m;
  m.tiltVariation = 0.0;
  m.roughnessVariation = 0.0;
  o.read("eta", m.eta);
  o.read("absorption", m.absorption);
  o.read("alpha_r_rad", m.alphaR);
  o.read("beta_r_rad", m.betaR);
  o.read("kg", m.kG);
  o.read("wc_rad", m.wc);
  o.read("deta", m.dEta);
  o.read("dhm", m.dhM);
  o.read("beta_n_rad", m.betaN);
  o.read("tilt_variation_rad", m.tiltVariation);
  o.read("roughness_variation", m.roughnessVariation);
  o.finish();
  try {
    m.validate();
  } catch (const Error& e) {
    throw Error(o.here() + ": " + e.what());  // "frame.json: /fibre/material: HairMaterial.eta = 5 is invalid"
  }
  return m;
}

// A per-strand list of /fibre (none in files older than `since`): each a number within `bound` of `centre`.
struct PerStrandList {
  const char* key;
  std::uint32_t since;
  double centre, bound;
  const char* versionRule;  // the refusal when an older file holds values
  std::string rule;         // the refusal when a value is out of bounds or not a number
};

std::vector<float> readPerStrand(JsonObject& fibre, const PerStrandList& l, std::uint32_t version) {
  std::vector<float> values;
  const nlohmann::json* list = fibre.array(l.key);
  if (!list) return values;
  if (version < l.since && !list->empty()) fibre.fail(l.key, l.versionRule);
  for (const nlohmann::json& v : *list) {
    if (!v.is_number() || !(std::abs(v.get<double>() - l.centre) <= l.bound)) fibre.fail(l.key, l.rule);
    values.push_back(v.get<float>());
  }
  return values;
}

// "strand_tilts_rad" (version 4): within the material's tilt variation of 0.
std::vector<float> readStrandTilts(JsonObject& fibre, const HairMaterial& m, std::uint32_t version) {
  return readPerStrand(fibre, {"strand_tilts_rad", 4, 0.0, m.tiltVariation * (1.0 + 1e-6), "per-strand tilts need version 4",
                               "each must be a number within the material's tilt_variation_rad, " +
                                   std::to_string(m.tiltVariation)},
                       version);
}

// "strand_roughness_scales" (version 5): within [1 - V, 1 + V], V the material's roughness variation.
std::vector<float> readStrandRoughness(JsonObject& fibre, const HairMaterial& m, std::uint32_t version) {
  return readPerStrand(fibre, {"strand_roughness_scales", 5, 1.0, m.roughnessVariation * (1.0 + 1e-6) + 1e-6,
                               "per-strand roughness needs version 5",
                               "each must be a number within 1 +- the material's roughness_variation, " +
                                   std::to_string(m.roughnessVariation)},
                       version);
}

JsonObject required(JsonObject& parent, const char* key) {
  auto o = parent.object(key);
  if (!o) parent.fail(key, "missing");
  return *o;
}

// Version 1 holds one "light" object, version 2 a "lights" list (possibly empty).
std::vector<LightSpec> readLights(JsonObject& o, std::uint32_t version) {
  if (version == 1) return {readLight(required(o, "light"), o.pointer("light"))};
  const nlohmann::json* list = o.array("lights");
  if (!list) o.fail("lights", "missing");
  if (list->size() > kMaxSceneLights)
    o.fail("lights", "at most " + std::to_string(kMaxSceneLights) + " lights, got " + std::to_string(list->size()));
  std::vector<LightSpec> lights;
  for (std::size_t i = 0; i < list->size(); ++i) {
    const std::string pointer = o.pointer("lights") + "/" + std::to_string(i);
    lights.push_back(readLight(JsonObject((*list)[i], pointer, o.file()), pointer));
  }
  return lights;
}

void readCamera(JsonObject o, FrameCameraSpec& c) {
  o.read("position", c.position);
  o.read("target", c.target);
  o.read("up", c.up);
  o.read("fov_y_deg", c.fovYDeg);
  o.read("width", c.width);
  o.read("height", c.height);
  o.finish();
  if (c.width < 1 || c.height < 1 || c.width > 16384 || c.height > 16384) o.fail("width", "width/height must be in [1, 16384]");
  if (!(c.fovYDeg > 0.0f && c.fovYDeg < 180.0f)) o.fail("fov_y_deg", "must be in (0, 180)");
  const glm::vec3 forward = c.target - c.position;
  if (!(glm::length(forward) > 0.0f) || !(glm::length(glm::cross(forward, c.up)) > 0.0f))
    o.fail("target", "the camera needs distinct position and target, and an up vector not along the view");
}

void readFrameJson(ExportedFrame& f, const std::filesystem::path& path) {
  // The scene file's parser: syntax, numbers past a double's range (1e999) and nesting past kMaxJsonDepth.
  const nlohmann::json root = parseJsonText(readInputText(path, kMaxTextFileBytes), path.string());
  JsonObject o(root, "", path.string());
  std::string format, units, up;
  std::uint32_t version = 0;
  o.read("format", format);
  o.read("version", version);
  if (format != kFormat || version < 1 || version > kVersion)
    o.fail("format", "expected format \"hairpipe-frame\", version 1 to 5");
  o.read("units", units);
  o.read("up", up);
  if (units != "metres" || up != "+y") o.fail("units", "expected units \"metres\" and up \"+y\"");
  o.value("files");
  o.value("tonemap");
  readCamera(required(o, "camera"), f.camera);
  f.lights = readLights(o, version);
  JsonObject fibre = required(o, "fibre");
  fibre.read("model", f.fibreModel);
  (void)reference::parseFibreModel(f.fibreModel);
  fibre.read("lut_mode", f.lutMode);
  try {
    (void)parseLutMode(f.lutMode);
  } catch (const Error&) {
    fibre.fail("lut_mode", "expected \"direct\", \"paper\", \"float\" or \"physical\"");
  }
  f.material = readMaterial(required(fibre, "material"));
  f.strandTilts = readStrandTilts(fibre, f.material, version);
  f.strandRoughness = readStrandRoughness(fibre, f.material, version);
  fibre.read("albedo", f.hairAlbedo);
  if (!inUnitRange(f.hairAlbedo)) fibre.fail("albedo", "each channel must be in [0, 1]");
  fibre.finish();
  JsonObject skin = required(o, "skin");
  skin.read("color", f.skinColor);
  skin.read("wrap", f.wrap);
  if (!inUnitRange(f.skinColor)) skin.fail("color", "each channel must be in [0, 1]");
  if (!inUnitRange(glm::vec3(f.wrap))) skin.fail("wrap", "must be in [0, 1]");
  skin.finish();
  o.read("environment_radiance", f.environment);
  if (auto map = o.object("environment_map")) f.environmentMap = readEnvironmentMap(*map, path.parent_path());
  o.read("background_radiance", f.background);
  o.read("exposure", f.exposure);
  o.finish();
  if (!(f.environment >= 0.0f) || !std::isfinite(f.environment)) o.fail("environment_radiance", "must be >= 0");
  if (!(f.background.x >= 0.0f && f.background.y >= 0.0f && f.background.z >= 0.0f) ||
      !std::isfinite(f.background.x + f.background.y + f.background.z))
    o.fail("background_radiance", "each channel must be finite and >= 0");
  if (!(f.exposure > 0.0f) || !std::isfinite(f.exposure)) o.fail("exposure", "must be > 0");
}

void checkStrands(const HairFileData& h, const std::string& source) {
  validateHairData(h, source);
  if (h.thickness.size() != h.points.size() || h.colors.size() != h.points.size())
    throw Error(source + ": a frame export needs per-point thickness and colour arrays");
  for (float t : h.thickness)
    if (!(t > 0.0f) || !std::isfinite(t)) throw Error(source + ": thickness must be positive and finite");
  for (const glm::vec3& c : h.colors)
    if (!(c.x >= 0 && c.y >= 0 && c.z >= 0) || !std::isfinite(c.x + c.y + c.z))
      throw Error(source + ": colours must be finite and >= 0");
}
}  // namespace

std::vector<float> ExportedFrame::strandColorScales() const {
  // The channel with the largest albedo carries the scale with the best precision.
  int c = 0;
  for (int i = 1; i < 3; ++i)
    if (hairAlbedo[i] > hairAlbedo[c]) c = i;
  std::vector<float> scales;
  const auto offsets = strands.strandOffsets();
  for (std::uint32_t s = 0; s < strands.strandCount; ++s)
    scales.push_back(hairAlbedo[c] > 0.0f ? strands.colors[offsets[s]][c] / hairAlbedo[c] : 1.0f);
  return scales;
}

HairMaterial ExportedFrame::strandMaterial(std::uint32_t s) const {
  HairMaterial m = material;
  if (s < strandTilts.size()) m.alphaR += strandTilts[s];
  if (s < strandRoughness.size()) m.betaR *= strandRoughness[s];
  return m;
}

namespace {
// Each strand's value of `perStrand` (strandTilt, strandRoughness) at `variation` as the real-time shading took
// it (the shader reads it as a float); none where that is 0 or the LUT mode is one of a single fibre (paper, float).
std::vector<float> strandValuesOf(const FrameCapture& frame, double variation, LutMode mode,
                                  float (*perStrand)(float random, float variation)) {
  std::vector<float> values;
  if (float(variation) == 0.0f || mode == LutMode::Paper || mode == LutMode::Float) return values;
  for (const auto& a : frame.strands.attributes) values.push_back(perStrand(a.random, float(variation)));
  return values;
}

// A per-strand list read from `json` holds one value per strand of the frame, or none.
void requireOnePerStrand(const std::vector<float>& values, const ExportedFrame& f, const std::filesystem::path& json,
                         const char* key, const char* what) {
  if (!values.empty() && values.size() != f.strands.strandCount)
    throw Error(json.string() + ": /fibre/" + key + ": " + std::to_string(values.size()) + " " + what + " for " +
                std::to_string(f.strands.strandCount) + " strands");
}
}  // namespace

ExportedFrame makeExportedFrame(const RenderRequest& request, const HairAsset& asset, const FrameCapture& frame,
                                const std::string& fibreModel) {
  const Scene& scene = request.scene;
  ExportedFrame f;
  f.fibreModel = fibreModel;
  f.lutMode = lutModeName(request.lutMode);
  f.material = scene.material;
  f.hairAlbedo = glm::vec3(glm::exp(-2.0 * scene.material.absorption));  // compute/raster/frame_block.cpp
  f.skinColor = request.look.skinColor;
  f.wrap = request.look.wrap;
  f.environment = request.look.ambient;
  f.environmentMap = request.environment;
  f.background = kBackgroundRadiance;
  f.exposure = request.exposure;
  f.lights = scene.lights;
  for (LightSpec& l : f.lights) l.direction = glm::normalize(l.direction);
  f.camera = {frame.camera.position, scene.camera.target, {0.0f, 1.0f, 0.0f}, scene.camera.fovDeg,
              scene.render.width, scene.render.height};
  f.strands = exportStrands(frame, request.look, f.hairAlbedo);
  f.strandTilts = strandValuesOf(frame, f.material.tiltVariation, request.lutMode, gpu::strandTilt);
  f.strandRoughness = strandValuesOf(frame, f.material.roughnessVariation, request.lutMode, gpu::strandRoughness);
  exportHead(f, request.drawHead ? asset.head : HeadMesh{}, frame.headToWorld);  // hair only: no head
  return f;
}

void writeFrameExport(const std::filesystem::path& dir, const ExportedFrame& frame) {
  // frame.json goes first and comes back last: an export whose later file fails to write leaves no frame.json
  // beside the new files, rather than an earlier export's that `reference --frame` would read with them.
  removeBeforeRewrite(dir / FrameExportFiles::json);
  writeHairFile(dir / FrameExportFiles::strands, frame.strands);
  writeAlbedoObj(dir / FrameExportFiles::head, {frame.headPositions, frame.headNormals, frame.headAlbedo, frame.headIndices});
  if (frame.environmentMap) writePfm(dir / FrameExportFiles::environment, environmentImage(*frame.environmentMap));
  const std::string text = hp::jsonText(frameJson(frame)) + "\n";
  writeFileAtomically(dir / FrameExportFiles::json, std::as_bytes(std::span(text.data(), text.size())));
}

ExportedFrame readFrameExport(const std::filesystem::path& dir) {
  if (!std::filesystem::is_directory(dir)) throw Error("'" + dir.string() + "' is not a frame export folder");
  ExportedFrame f;
  readFrameJson(f, dir / FrameExportFiles::json);
  f.strands = readHairFile(dir / FrameExportFiles::strands);
  checkStrands(f.strands, (dir / FrameExportFiles::strands).string());
  requireOnePerStrand(f.strandTilts, f, dir / FrameExportFiles::json, "strand_tilts_rad", "tilts");
  requireOnePerStrand(f.strandRoughness, f, dir / FrameExportFiles::json, "strand_roughness_scales", "scales");
  AlbedoMesh head = readAlbedoObj(dir / FrameExportFiles::head);
  f.headPositions = std::move(head.positions);
  f.headNormals = std::move(head.normals);
  f.headAlbedo = std::move(head.albedo);
  f.headIndices = std::move(head.indices);
  return f;
}
}  // namespace hp
