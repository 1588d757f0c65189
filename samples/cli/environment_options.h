#pragma once
// Contract: the environment light's options of the frame commands (`render`, `reference`, `view`):
// --environment none|studio|FILE (.hdr or .pfm, equirectangular), --environment-intensity,
// --environment-rotation, --environment-lights. applyEnvironmentOptions builds the environment they name,
// turned and scaled, and splits it for the real-time frame (engine/core/shading/environment_lights.h): its
// bright regions become shadowed directional lights (RenderRequest::environmentLights), the rest the look's
// SH; the uniform ambient becomes 0 (the environment is the sky). hp::Error naming the option or the file.
// docs/SHADING.md "Environment".
#include <CLI/CLI.hpp>

#include <string>

#include "samples/tools/render_job.h"

namespace hp::cli {
struct EnvironmentOptions {
  std::string source = "none";
  double intensity = 1.0;
  double rotationDeg = 0.0;
  std::uint32_t lights = 2;
};

void addEnvironmentOptions(CLI::App& cmd, EnvironmentOptions& o);
void applyEnvironmentOptions(const EnvironmentOptions& o, RenderRequest& request);
}  // namespace hp::cli
