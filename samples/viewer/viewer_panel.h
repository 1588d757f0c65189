#pragma once
// Contract: the viewer's Dear ImGui panel: simulation (animation, wind, pause, solver), density,
// material and scattering (the Marschner lobes, LUT mode), lights (add up to 8, remove; per light its type,
// direction or position and target, colour, intensity, range, cone, shadows), shadows (opacity maps), look, groom
// (exposure, ambient, strand width), groom (clumps, curl, frizz) and the last completed frame's GPU time per pass. It edits a Tunables
// copy; the frame loop applies what changed (the flags) through the hair's setters between frames (the
// lights go into every frame as they are), and a setter's hp::Error comes back as `error`, shown in the
// panel instead of ending the viewer. The panel keeps every light valid (LightSpec::validate): directions
// unit, spots aimed away from their target, values inside their ranges.
#include <string>
#include <vector>

#include "engine/core/hair/scene.h"
#include "compute/raster/frame_block.h"
#include "compute/shadows/opacity_settings.h"
#include "engine/core/shading/lut.h"
#include "engine/vk/profiler.h"
#include "samples/viewer/view_state.h"

namespace hp::viewer {
struct Tunables {
  SimulationParams simulation;
  double windStrength = 4.0;         // what W turns on (scene units / s^2)
  std::uint32_t density = 20000;     // render strands in total
  HairMaterial material;
  LutMode lutMode = LutMode::Physical;
  render::OpacitySettings opacity;
  render::LookSettings look;
  hairpipe::LodSettings lod;
  float exposure = 1.0f;
  std::vector<EditedLight> lights;   // the frame's lights, the first turned by the light drag too
  GroomSettings groom;
};

struct PanelChanges {
  bool simulation = false;
  bool density = false;   // "apply" pressed: rebuild the strands
  bool material = false;  // "apply" pressed: rebuild the lookup textures
  bool opacity = false;
  bool look = false;
  bool lod = false;
  bool groom = false;
};

struct PanelStatus {
  std::vector<vk::ScopeTime> passTimes;  // the last completed frame's
  double frameMs = 0.0;                  // wall time per frame, smoothed
  std::string device;
  std::string raster;
  std::uint32_t strands = 0;
  std::string error;                     // the last setter's refusal, if any
  bool startCollapsed = false;           // a small window: the panel starts as its title bar
};

PanelChanges drawPanel(Tunables& tunables, ViewState& view, const PanelStatus& status);
}  // namespace hp::viewer
