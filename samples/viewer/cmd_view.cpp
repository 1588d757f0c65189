// `hairpipe view`: the live viewer (viewer_app.h). Registered into the tool only (not the CLI fuzzer's
// command set): it is the one command that opens a window.
#include <cmath>
#include <cstdio>
#include <iostream>

#include <nlohmann/json.hpp>

#include "engine/core/error.h"
#include "samples/tools/character_clip.h"
#include "samples/tools/host/camera_fit.h"
#include "samples/tools/render_job.h"
#include "engine/vk/check.h"
#include "samples/cli/command.h"
#include "samples/cli/frame_options.h"
#include "samples/cli/material_options.h"
#include "samples/cli/output_paths.h"
#include "samples/viewer/viewer_app.h"
#include "samples/tools/host/json_text.h"

namespace {
constexpr std::uint32_t kMaxFrames = 1000000;
constexpr std::uint32_t kMaxWindowSide = 16384;

struct ViewOptions {
  hp::cli::SceneOptions scene;
  hp::HairMaterial material;
  std::optional<std::uint32_t> width, height, msaa, density, opacityResolution;
  bool noShadows = false;
  std::optional<std::string> raster;
  std::string lutMode = "physical";
  std::string animate = "none";
  float exposure = 1.0f;
  std::uint32_t frames = 0;
  std::string screenshot;
  std::string resizeAt;
  std::string minimiseAt;
  std::vector<std::string> faultsAt;
  std::vector<std::string> lights;  // --light SPEC: the panel's lights to start with
  bool noPanel = false;
  bool json = false;
};

// "K:WxH": at frame K the window is resized to W x H.
void parseResize(const std::string& text, hp::viewer::ViewerOptions& v) {
  unsigned k = 0, w = 0, h = 0;
  char tail = 0;
  if (std::sscanf(text.c_str(), "%u:%ux%u%c", &k, &w, &h, &tail) != 3 || w == 0 || h == 0 || w > kMaxWindowSide ||
      h > kMaxWindowSide)
    throw hp::Error("--resize-at takes FRAME:WIDTHxHEIGHT with sides in [1, 16384], e.g. 10:200x150");
  v.resizeAt = k;
  v.resizeTo = {w, h};
}

// "K:S": at frame K the window is minimised for S seconds.
void parseMinimise(const std::string& text, hp::viewer::ViewerOptions& v) {
  unsigned k = 0;
  double seconds = 0.0;
  char tail = 0;
  if (std::sscanf(text.c_str(), "%u:%lf%c", &k, &seconds, &tail) != 2 || !(seconds > 0.0) || seconds > 60.0)
    throw hp::Error("--minimise-at takes FRAME:SECONDS with seconds in (0, 60], e.g. 10:0.5");
  v.minimiseAt = k;
  v.minimiseSeconds = seconds;
}

// "K:CALL:RESULT": from frame K, the next success of CALL reports RESULT. Only the calls and results
// whose injection is faithful (the call has done its work when it returns; see vk::armFault).
hp::viewer::ScriptedFault parseFault(const std::string& text) {
  const std::string usage =
      "--fault-at takes FRAME:CALL:RESULT with CALL vkWaitForFences, vkQueueSubmit2 or vkQueuePresentKHR and "
      "RESULT VK_ERROR_DEVICE_LOST, or vkQueuePresentKHR with VK_ERROR_OUT_OF_DATE_KHR or VK_SUBOPTIMAL_KHR";
  const std::size_t a = text.find(':'), b = a == std::string::npos ? a : text.find(':', a + 1);
  if (b == std::string::npos) throw hp::Error(usage);
  hp::viewer::ScriptedFault f;
  f.call = text.substr(a + 1, b - a - 1);
  const std::string result = text.substr(b + 1);
  unsigned k = 0;
  char tail = 0;
  if (std::sscanf(text.substr(0, a).c_str(), "%u%c", &k, &tail) != 1) throw hp::Error(usage);
  f.frame = k;
  const bool present = f.call == "vkQueuePresentKHR";
  for (VkResult r : {VK_ERROR_DEVICE_LOST, VK_ERROR_OUT_OF_DATE_KHR, VK_SUBOPTIMAL_KHR})
    if (result == hp::vk::resultName(r)) f.result = r;
  const bool lost = f.result == VK_ERROR_DEVICE_LOST &&
                    (present || f.call == "vkWaitForFences" || f.call == "vkQueueSubmit2");
  if (!lost && !(present && f.result != VK_SUCCESS)) throw hp::Error(usage);
  return f;
}

hp::viewer::ViewerOptions viewerOptions(const ViewOptions& o, const CLI::App& cmd) {
  hp::viewer::ViewerOptions v;
  v.scene = o.scene;
  hp::RenderRequest& r = v.request;
  r.scene = hp::cli::loadScene(o.scene);
  hp::cli::replaceLights(o.lights, r.scene);
  if (o.width) r.scene.render.width = *o.width;
  if (o.height) r.scene.render.height = *o.height;
  if (r.scene.render.width == 0 || r.scene.render.height == 0 || r.scene.render.width > kMaxWindowSide ||
      r.scene.render.height > kMaxWindowSide)
    throw hp::Error("--width/--height must be in [1, 16384]");
  if (o.msaa) r.scene.render.msaa = *o.msaa;
  if (hp::cli::materialGiven(cmd)) r.scene.material = o.material;
  if (o.raster) r.scene.render.raster = hp::parseRasterMode(*o.raster);
  if (o.density) {
    r.scene.density.mode = hp::DensityOptions::Mode::Total;
    r.scene.density.totalStrands = *o.density;
    r.scene.density.validate();
  }
  r.opacity.enabled = !o.noShadows;
  if (o.opacityResolution) r.opacity.resolution = *o.opacityResolution;
  hp::render::validate(r.opacity);
  r.lutMode = hp::parseLutMode(o.lutMode);
  if (const auto clip = hp::clipOfAnimate(o.animate)) r.characterClip = *clip;
  else r.animation = hp::parseHeadAnimation(o.animate);
  hp::validateExposure(o.exposure, "--exposure");
  r.exposure = o.exposure;
  if (o.frames > kMaxFrames) throw hp::Error("--frames must be at most 1000000 (0: until the window closes)");
  v.frames = o.frames;
  if (!o.screenshot.empty() && o.frames == 0) throw hp::Error("--screenshot needs --frames N (the frame it saves)");
  v.screenshot = o.screenshot;
  if (!o.resizeAt.empty()) parseResize(o.resizeAt, v);
  if (!o.minimiseAt.empty()) parseMinimise(o.minimiseAt, v);
  for (const std::string& f : o.faultsAt) v.faults.push_back(parseFault(f));
  v.panel = !o.noPanel;
  hp::validateRequest(r);
  return v;
}

void runView(const ViewOptions& o, const CLI::App& cmd) {
  hp::viewer::ViewerOptions v = viewerOptions(o, cmd);
  if (!v.screenshot.empty())
    hp::cli::prepareOutputFile({"--screenshot", v.screenshot}, hp::cli::sceneInputs(o.scene, v.request.scene));
  const hp::HairAsset asset = hp::buildSceneAsset(v.request.scene);
  if (v.request.scene.fitCamera) hp::fitCameraToPoints(v.request.scene.camera, asset.guides.positions);
  const hp::viewer::ViewerReport report = hp::viewer::runViewer(v, asset);
  const nlohmann::json j = {{"frames", report.frames},
                            {"swapchain_recreations", report.swapchainRecreations},
                            {"minimised_waits", report.minimisedWaits},
                            {"device_losses", report.deviceLosses},
                            {"width", report.extent.width},
                            {"height", report.extent.height},
                            {"device", report.device},
                            {"raster", report.raster},
                            {"screenshot", v.screenshot}};
  if (o.json) {
    std::cout << hp::jsonText(j) << "\n";
    return;
  }
  std::cout << "viewed " << report.frames << " frames (" << report.extent.width << "x" << report.extent.height
            << ", swapchain recreated " << report.swapchainRecreations << "x, " << report.raster << " raster) on "
            << report.device << "\n";
  if (report.deviceLosses > 0) std::cout << "the device was lost " << report.deviceLosses << "x and replaced\n";
  if (!v.screenshot.empty()) std::cout << "wrote " << v.screenshot << "\n";
}

void setupView(CLI::App& app) {
  auto o = std::make_shared<ViewOptions>();
  CLI::App* cmd = app.add_subcommand(
      "view", "Live viewer: drag orbits, wheel zooms, Shift+drag or right drag turns the light, N/T/S nod/turn/"
              "shake, W wind, Space pause, F1 panel, Esc quits");
  hp::cli::addSceneOptions(*cmd, o->scene);
  hp::cli::addMaterialOptions(*cmd, o->material);
  cmd->add_option("--width", o->width, "Window width (default: scene, 1280)");
  cmd->add_option("--height", o->height, "Window height (default: scene, 720)");
  cmd->add_option("--msaa", o->msaa, "Samples per pixel of the graphics raster (default: scene, 4)");
  cmd->add_option("--raster", o->raster, "Hair drawing: auto (= compute), compute or graphics (default: scene)");
  cmd->add_option("--density", o->density, "Render strands in total (default: scene, 20000)");
  cmd->add_option("--opacity-resolution", o->opacityResolution, "Opacity map texels per side, 16-4096 (default 512)");
  cmd->add_flag("--no-shadows", o->noShadows, "Start with the opacity shadow maps off");
  cmd->add_option("--lut-mode", o->lutMode, "fibre model: physical (energy-conserving, default; dual scattering needs it), or the paper's model as float, paper or direct");
  cmd->add_option("--animate", o->animate, "Head motion at the start: none, nod, turn, shake, or clip:NAME (an animation clip of the --mesh "
                  "character, looped: its body posed, collided with and drawn, the roots following its bones)");
  cmd->add_option("--exposure", o->exposure, "Exposure multiplier before tonemapping (default 1)");
  hp::cli::addLightOption(*cmd, o->lights);
  cmd->add_option("--frames", o->frames, "Stop after N frames (default 0: when the window closes)");
  cmd->add_option("--screenshot", o->screenshot, "With --frames N: save the last frame's window image as PNG");
  cmd->add_option("--resize-at", o->resizeAt, "Testing: resize the window at a frame, FRAME:WxH");
  cmd->add_option("--minimise-at", o->minimiseAt, "Testing: minimise the window at a frame for a while, FRAME:SECONDS");
  cmd->add_option("--fault-at", o->faultsAt,
                  "Testing: from a frame on, the next success of a Vulkan call reports a failure, "
                  "FRAME:CALL:RESULT (e.g. 5:vkWaitForFences:VK_ERROR_DEVICE_LOST); repeatable");
  cmd->add_flag("--no-panel", o->noPanel, "Start with the panel hidden (F1 shows it)");
  cmd->add_flag("--json", o->json, "Print the run's summary as JSON");
  cmd->callback([o, cmd] { runView(*o, *cmd); });
}
}  // namespace

HP_CLI_COMMAND(setupView);
