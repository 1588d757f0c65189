#pragma once
// Contract: the options that define a rendered frame (scene, size, light, camera, material, LUT mode,
// shadows, raster, settling), shared by `hairpipe render` and `hairpipe reference` so both commands
// take exactly the same frame description. addFrameOptions registers them on a subcommand;
// makeRenderRequest validates them (hp::Error naming the option) into a RenderRequest; frameCamera
// frames a guessed model's camera and refuses a frame with no hair in view.
#include <CLI/CLI.hpp>

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

#include "samples/cli/environment_options.h"
#include "samples/cli/groom_options.h"
#include "samples/cli/hair_grid_options.h"
#include "samples/cli/scene_options.h"
#include "samples/tools/render_job.h"

namespace hp::cli {
struct FrameOptions {
  SceneOptions scene;
  GroomOptions groom;
  HairGridOptions grid;
  EnvironmentOptions environment;
  HairMaterial material;
  std::uint32_t frames = 90;
  std::optional<std::uint32_t> width, height, msaa, density;
  bool ownStrands = false;  // one render strand on every guide (--own-strands)
  std::vector<std::string> lights;  // --light SPEC, repeatable (samples/tools/host/light_option.h)
  std::optional<std::vector<float>> lightDir, spot, spotTarget;
  std::optional<float> spotAngle, spotRange;
  std::optional<float> orbit;
  std::optional<float> ambient;
  std::optional<std::string> scattering;
  std::optional<std::string> skinBounce;  // on | off
  std::optional<std::string> skinIndirect;  // on | off
  std::optional<std::string> farSide;     // depth | open
  std::optional<std::vector<float>> skinColor;
  std::optional<float> wrap;  // the skin's wrap lighting
  std::string lutMode = "physical";
  std::string animate = "none";
  float exposure = 1.0f;
  bool lines = false;
  bool guidesOnly = false;
  std::uint32_t bounceSamples = hp::gpu::RENDER_BOUNCE_STRAND_SAMPLES;
  bool hairOnly = false;
  std::vector<float> lod;  // START,END,MIN: level of detail by distance
  bool noShadows = false;
  bool deepOpacity = true;
  std::optional<std::uint32_t> opacityResolution;
  std::optional<std::uint32_t> shadowStrands;
  std::optional<float> strandOpacity, shadowK, shadowBias;
  std::optional<std::string> raster, opacityRaster;
  std::optional<std::uint32_t> tileBudget;
  std::optional<float> shadingSpacing;
};

void addFrameOptions(CLI::App& cmd, FrameOptions& o);
// `--light SPEC` (repeatable; samples/tools/host/light_option.h), for the commands that take lights.
void addLightOption(CLI::App& cmd, std::vector<std::string>& specs);
// Given specs replace the scene's lights (spot targets default to its camera target); none: unchanged.
// hp::Error naming the option, the spec and the bad key, or more than kMaxSceneLights.
void replaceLights(const std::vector<std::string>& specs, Scene& scene);
RenderRequest makeRenderRequest(const FrameOptions& o, const CLI::App& cmd);
// A model loaded without a scene: frame the camera on its hair (said on stderr); returns what was
// guessed (empty object: nothing). Throws when no guide particle is in view.
nlohmann::json frameCamera(Scene& scene, const HairAsset& asset);
}  // namespace hp::cli
