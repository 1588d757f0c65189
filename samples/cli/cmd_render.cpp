// `hairpipe render`: simulates N frames so the hair settles, renders the last one (head + hair with
// Marschner shading, opacity shadow maps), writes the PNG atomically and prints the GPU time of every
// pass. --dump-opacity DIR also writes the 16 opacity slices (PFM), a contact sheet (PNG) and the
// slice depths (JSON).
#include <cmath>
#include <iostream>

#include <nlohmann/json.hpp>

#include "engine/error.h"
#include "engine/hair/camera_fit.h"
#include "samples/tools/png_file.h"
#include "samples/tools/render_job.h"
#include "samples/cli/command.h"
#include "samples/cli/material_options.h"
#include "samples/cli/scene_options.h"
#include "samples/cli/output_paths.h"

namespace {
struct RenderOptions {
  hp::cli::SceneOptions scene;
  hp::HairMaterial material;
  bool materialGiven = false;
  std::uint32_t frames = 90;
  std::optional<std::uint32_t> width, height, msaa, density;
  std::optional<std::vector<float>> lightDir, spot, spotTarget;
  std::optional<float> spotAngle, spotRange;
  std::optional<float> orbit;
  std::string lutMode = "physical";
  std::string animate = "none";
  std::string out = "out/hair.png";
  float exposure = 1.0f;
  bool lines = false;
  bool guidesOnly = false;
  bool json = false;
  bool noShadows = false;
  std::optional<std::uint32_t> opacityResolution;
  std::optional<float> strandOpacity, shadowK, shadowBias;
  std::string dumpOpacity;
  std::string dumpStrands;
  std::optional<std::string> raster;
  std::optional<std::uint32_t> tileBudget;
};

// --raster overrides the scene's; --lines are graphics lines, so they pick the graphics path unless
// the compute one was asked for by name (refused).
void applyRaster(const RenderOptions& o, hp::RenderRequest& r) {
  if (o.raster) r.scene.render.raster = hp::parseRasterMode(*o.raster);
  if (o.lines) {
    if (r.scene.render.raster == hp::RasterMode::Compute)
      throw hp::Error("--lines draws graphics lines: use --raster graphics (or auto) with it");
    r.scene.render.raster = hp::RasterMode::Graphics;
  }
  if (o.tileBudget) r.rasterSettings.tileBudget = *o.tileBudget;
  r.rasterSettings.validate();
}

hp::render::OpacitySettings opacitySettings(const RenderOptions& o) {
  hp::render::OpacitySettings s;
  s.enabled = !o.noShadows;
  if (o.opacityResolution) s.resolution = *o.opacityResolution;
  if (o.strandOpacity) {
    s.footprint = false;  // a constant per crossing replaces the width / texel-size footprint
    s.strandOpacity = *o.strandOpacity;
  }
  if (o.shadowK) s.k = *o.shadowK;
  if (o.shadowBias) s.biasSlices = *o.shadowBias;
  s.validate();
  if (!o.dumpOpacity.empty() && !s.enabled) throw hp::Error("--dump-opacity needs opacity shadows (drop --no-shadows)");
  return s;
}

glm::vec3 vec3Option(const std::vector<float>& v, const char* name) {
  if (v.size() != 3) throw hp::Error(std::string(name) + " takes X,Y,Z");
  const glm::vec3 p{v[0], v[1], v[2]};
  if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
    throw hp::Error(std::string(name) + " must be finite");
  return p;
}

// --spot POS [--spot-target P] [--spot-angle DEG] [--spot-range R]: a spot light aimed at the
// target (default: the camera's target); each bad value names its option.
void applySpot(const RenderOptions& o, hp::Scene& scene) {
  if (!o.spot) {
    if (o.spotTarget || o.spotAngle || o.spotRange) throw hp::Error("--spot-target/--spot-angle/--spot-range need --spot");
    return;
  }
  if (o.lightDir) throw hp::Error("--spot and --light-dir are exclusive");
  const glm::vec3 position = vec3Option(*o.spot, "--spot");
  const glm::vec3 target = o.spotTarget ? vec3Option(*o.spotTarget, "--spot-target") : scene.camera.target;
  if (glm::length(position - target) < 1e-6f) throw hp::Error("--spot-target must differ from the --spot position");
  const float angle = o.spotAngle.value_or(30.0f);
  if (!(angle > 0.0f && angle <= 80.0f)) throw hp::Error("--spot-angle must be in (0, 80] degrees");
  const float range = o.spotRange.value_or(0.0f);
  if (!(std::isfinite(range) && range >= 0.0f)) throw hp::Error("--spot-range must be >= 0 (0: no distance falloff)");
  hp::LightSpec light = hp::LightSpec::makeSpot(position, target, angle);
  light.range = range;
  light.color = scene.light.color;
  light.intensity = scene.light.intensity;
  scene.light = light;
}

hp::RenderRequest makeRequest(const RenderOptions& o, const CLI::App& cmd) {
  hp::RenderRequest r;
  r.scene = hp::cli::loadScene(o.scene);
  if (o.width) r.scene.render.width = *o.width;
  if (o.height) r.scene.render.height = *o.height;
  if (o.msaa) r.scene.render.msaa = *o.msaa;
  if (o.density) {
    r.scene.density.mode = hp::DensityOptions::Mode::Total;
    r.scene.density.totalStrands = *o.density;
    r.scene.density.validate();
  }
  if (o.lightDir) {
    if (o.lightDir->size() != 3) throw hp::Error("--light-dir takes X,Y,Z");
    r.scene.light.direction = {(*o.lightDir)[0], (*o.lightDir)[1], (*o.lightDir)[2]};
    if (!(glm::length(r.scene.light.direction) > 1e-6f) || !std::isfinite(glm::length(r.scene.light.direction)))
      throw hp::Error("--light-dir must be a non-zero finite vector");
    r.scene.light.direction = glm::normalize(r.scene.light.direction);
    r.scene.light.type = hp::LightSpec::Type::Directional;  // overrides a scene's spot
  }
  if (o.orbit) r.scene.camera.orbitDeg = *o.orbit;
  applySpot(o, r.scene);
  if (cmd.count("--eta") + cmd.count("--absorption") + cmd.count("--color") + cmd.count("--alpha-r") +
          cmd.count("--beta-r") + cmd.count("--kg") + cmd.count("--wc") + cmd.count("--deta") + cmd.count("--dhm") +
              cmd.count("--beta-n") > 0)
    r.scene.material = o.material;
  if (r.scene.render.width == 0 || r.scene.render.height == 0 || r.scene.render.width > 16384 ||
      r.scene.render.height > 16384)
    throw hp::Error("--width/--height must be in [1, 16384]");
  r.settleFrames = o.frames;
  r.animation = hp::parseHeadAnimation(o.animate);
  r.lutMode = hp::parseLutMode(o.lutMode);
  r.lines = o.lines;
  r.guidesOnly = o.guidesOnly;
  r.exposure = o.exposure;
  r.opacity = opacitySettings(o);
  r.captureOpacity = !o.dumpOpacity.empty();
  r.captureStrands = !o.dumpStrands.empty();
  applyRaster(o, r);
  return r;
}

// A model loaded without a scene: frame the camera on its hair (the orbit and elevation stay). Any
// frame: refuse one in which no guide particle falls inside the view, naming why.
nlohmann::json frameCamera(hp::Scene& scene, const hp::HairAsset& asset) {
  nlohmann::json guessed = nlohmann::json::object();
  if (scene.fitCamera) {
    hp::fitCameraToPoints(scene.camera, asset.guides.positions);
    const auto& c = scene.camera;
    guessed = {{"model", scene.guessed},
               {"camera", {{"target", {c.target.x, c.target.y, c.target.z}}, {"distance", c.distance}}}};
    std::cerr << "hairpipe: guessed " << scene.guessed << "; camera framed on the hair (target " << c.target.x
              << ", " << c.target.y << ", " << c.target.z << ", distance " << c.distance << ")\n";
  }
  const float aspect = float(scene.render.width) / float(scene.render.height);
  if (hp::pointsInView(scene.camera, aspect, asset.guides.positions) == 0) {
    const auto& c = scene.camera;
    throw hp::Error("no hair is visible: all " + std::to_string(asset.guides.positions.size()) +
                    " guide particles of " + asset.name + " are outside the camera's view (target " +
                    std::to_string(c.target.x) + ", " + std::to_string(c.target.y) + ", " + std::to_string(c.target.z) +
                    ", distance " + std::to_string(c.distance) + ", orbit " + std::to_string(c.orbitDeg) +
                    "); check the model's units/up axis or the camera");
  }
  return guessed;
}

// Every output checked (not an input, folder writable) before the simulation starts.
void prepareOutputs(const RenderOptions& o, const hp::Scene& scene) {
  const std::vector<hp::cli::CommandPath> inputs = hp::cli::sceneInputs(o.scene, scene);
  hp::cli::prepareOutputFile({"--out", o.out}, inputs);
  if (!o.dumpStrands.empty()) hp::cli::prepareOutputFile({"--dump-strands", o.dumpStrands}, inputs);
  if (!o.dumpOpacity.empty()) hp::cli::prepareOutputFolder({"--dump-opacity", o.dumpOpacity}, inputs);
}

void runRender(const RenderOptions& o, const CLI::App& cmd) {
  hp::RenderRequest request = makeRequest(o, cmd);
  prepareOutputs(o, request.scene);
  hp::HairAsset asset = hp::buildSceneAsset(request.scene);
  const nlohmann::json guessed = frameCamera(request.scene, asset);
  auto ctx = hp::cli::createContext(o.scene);
  hp::RenderResult result = hp::renderStill(*ctx, asset, request);
  hp::cli::checkValidation(*ctx);
  hp::writePng(o.out, result.width, result.height, 4, result.rgba);
  if (result.opacity) hp::render::writeOpacityDump(o.dumpOpacity, *result.opacity);
  if (result.strandDump) hp::writeHairFile(o.dumpStrands, *result.strandDump);
  nlohmann::json passes = nlohmann::json::object();
  for (const auto& t : result.passTimes) passes[t.name] = t.milliseconds;
  nlohmann::json report = {{"out", o.out},        {"width", result.width},   {"height", result.height},
                           {"guides", result.guides}, {"strands", result.strands},
                           {"vertices_per_strand", result.verticesPerStrand},
                           {"lut_mode", o.lutMode}, {"device", ctx->properties().deviceName},
                           {"gpu_ms", passes}, {"raster", hp::rasterModeName(result.raster)}};
  if (!guessed.empty()) report["guessed"] = guessed;
  if (result.rasterStats) {
    const auto& s = *result.rasterStats;
    report["raster_lists"] = {{"requested", s.requested}, {"kept", s.kept},
                              {"dropped_tile_budget", s.droppedByTileBudget},
                              {"dropped_capacity", s.droppedByCapacity}, {"overflow", s.overflow()}};
  }
  if (result.opacity) report["opacity_dump"] = o.dumpOpacity;
  if (result.strandDump) report["strands_dump"] = o.dumpStrands;
  if (o.json) {
    std::cout << report.dump(2) << "\n";
    return;
  }
  std::cout << "wrote " << o.out << " (" << result.width << "x" << result.height << ", " << result.strands
            << " strands from " << result.guides << " guides) on " << ctx->properties().deviceName << "\n";
  std::cout << "  raster: " << hp::rasterModeName(result.raster) << "\n";
  if (result.rasterStats)
    std::cout << "  tile lists: " << result.rasterStats->kept << " entries kept of " << result.rasterStats->requested
              << ", overflow " << result.rasterStats->overflow() << " (tile budget "
              << result.rasterStats->droppedByTileBudget << ", capacity " << result.rasterStats->droppedByCapacity
              << ")\n";
  for (const auto& t : result.passTimes) std::cout << "  " << t.name << ": " << t.milliseconds << " ms\n";
}

void setupRender(CLI::App& app) {
  auto o = std::make_shared<RenderOptions>();
  CLI::App* cmd = app.add_subcommand("render", "Simulate, then render the last frame to a PNG");
  hp::cli::addSceneOptions(*cmd, o->scene);
  hp::cli::addMaterialOptions(*cmd, o->material);
  cmd->add_option("--frames", o->frames, "Frames simulated before the rendered one (default 90)");
  cmd->add_option("--width", o->width, "Image width (default: scene, 1280)");
  cmd->add_option("--height", o->height, "Image height (default: scene, 720)");
  cmd->add_option("--msaa", o->msaa, "Samples per pixel of the graphics raster: 1, 2, 4 or 8 (default: scene, 4)");
  cmd->add_option("--raster", o->raster,
                  "Hair drawing: compute (tile rasterizer, analytic coverage), graphics (MSAA ribbons) or auto "
                  "(default: scene, auto = compute)");
  cmd->add_option("--tile-budget", o->tileBudget, "Compute raster: list entries kept per 8x8 tile (default 16384)");
  cmd->add_option("--density", o->density, "Render strands in total (default: scene, 20000)");
  cmd->add_option("--light-dir", o->lightDir, "Direction toward the light, X,Y,Z")->delimiter(',')->expected(3);
  cmd->add_option("--spot", o->spot, "Spot light at X,Y,Z instead of the directional light")->delimiter(',')->expected(3);
  cmd->add_option("--spot-target", o->spotTarget, "Point the spot aims at, X,Y,Z (default: the camera target)")
      ->delimiter(',')->expected(3);
  cmd->add_option("--spot-angle", o->spotAngle, "Spot cone half-angle in degrees, (0, 80] (default 30)");
  cmd->add_option("--spot-range", o->spotRange, "Spot inverse-square falloff, 1 at this distance (default 0: none)");
  cmd->add_option("--camera-orbit", o->orbit, "Camera orbit around the head in degrees (0: from the front)");
  cmd->add_option("--lut-mode", o->lutMode, "fibre model: physical (energy-conserving, default), or the paper's model as float, paper or direct");
  cmd->add_option("--animate", o->animate, "Head motion while settling: none, nod, turn, shake, teleport");
  cmd->add_option("--exposure", o->exposure, "Exposure multiplier before tonemapping (default 1)");
  cmd->add_flag("--lines", o->lines, "Draw strands as lines instead of ribbons");
  cmd->add_flag("--guides-only", o->guidesOnly, "Draw the smoothed guides only (no interpolation)");
  cmd->add_flag("--no-shadows", o->noShadows, "Turn the opacity shadow maps off");
  cmd->add_option("--opacity-resolution", o->opacityResolution, "Opacity map texels per side, 16-4096 (default 512)");
  cmd->add_option("--strand-opacity", o->strandOpacity, "Constant opacity a strand adds per opacity-map texel instead of its footprint (width / texel size, the default)");
  cmd->add_option("--shadow-k", o->shadowK, "Extinction k in T = exp(-k alpha) (default 1)");
  cmd->add_option("--shadow-bias", o->shadowBias, "Shadow lookup bias toward the light, in slices (default 1)");
  cmd->add_option("--dump-strands", o->dumpStrands, "Write the rendered frame's render strands as .hair (Q points each)");
  cmd->add_option("--dump-opacity", o->dumpOpacity, "Write the 16 opacity slices (PFM), a contact sheet and the slice depths to DIR");
  cmd->add_option("--out", o->out, "Output PNG (default out/hair.png)");
  cmd->add_flag("--json", o->json, "Print JSON");
  cmd->callback([o, cmd] { runRender(*o, *cmd); });
}
}  // namespace

HP_CLI_COMMAND(setupRender);
