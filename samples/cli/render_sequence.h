#pragma once
// Contract: `hairpipe render --sequence DIR`: every frame of the animation as DIR/frame_0001.png ...
// (each written atomically), progress on stderr (ProgressReporter), Ctrl-C stopping after the current
// frame with only complete files left and an hp::Error saying how far it got, and optionally a
// contact sheet (--contact-sheet F.png: up to 12 frames evenly spread, 4 per row). --fps sets the
// simulation step of any render (dt = 1 / fps). Limits are checked before any work.
#include <optional>
#include <string>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "samples/cli/output_paths.h"
#include "samples/tools/render_job.h"

namespace hp::cli {
inline constexpr std::uint32_t kMaxSequenceFrames = 9999;  // frame_NNNN.png: four digits
inline constexpr double kMaxFps = 1000.0;

struct SequenceOptions {
  std::string dir;
  std::string contactSheet;
  std::optional<double> fps;
};

void addSequenceOptions(CLI::App& cmd, SequenceOptions& options);
double stepOfFps(double fps);  // throws hp::Error outside [1, kMaxFps]
void checkSequence(std::uint32_t frames);
void prepareSequenceOutputs(const SequenceOptions& options, const std::vector<CommandPath>& inputs);
std::string sequenceFrameName(std::uint32_t frame);  // "frame_0001.png"
void runSequence(const SequenceOptions& options, std::uint32_t frames, const RenderRequest& request,
                 const HairAsset& asset, const SceneOptions& scene, bool json, const nlohmann::json& guessed);
}  // namespace hp::cli
