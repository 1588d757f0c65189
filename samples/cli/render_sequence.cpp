#include "samples/cli/render_sequence.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iostream>

#include "engine/core/error.h"
#include "samples/tools/contact_sheet.h"
#include "samples/tools/interrupt_flag.h"
#include "samples/tools/progress_reporter.h"
#include "samples/tools/host/json_text.h"

namespace hp::cli {
namespace {
constexpr std::uint32_t kSheetTiles = 12;
constexpr std::uint32_t kSheetColumns = 4;

nlohmann::json report(const SequenceOptions& o, std::uint32_t frames, const RenderResult& last, double seconds,
                      const vk::Context& ctx) {
  nlohmann::json passes = nlohmann::json::object();
  for (const auto& t : last.passTimes) passes[t.name] = t.milliseconds;
  nlohmann::json r = {{"sequence", o.dir},       {"frames", frames},       {"width", last.width},
                      {"height", last.height},   {"first", o.dir + "/" + sequenceFrameName(1)},
                      {"last", o.dir + "/" + sequenceFrameName(frames)},  {"strands", last.strands},
                      {"frames_per_second", seconds > 0 ? frames / seconds : 0.0},
                      {"device", ctx.properties().deviceName},           {"gpu_ms_last_frame", passes},
                      {"raster", rasterModeName(last.raster)}};
  if (!o.contactSheet.empty()) r["contact_sheet"] = o.contactSheet;
  return r;
}
}  // namespace

void addSequenceOptions(CLI::App& cmd, SequenceOptions& o) {
  cmd.add_option("--sequence", o.dir, "Write every frame of the animation to DIR/frame_0001.png ... (--frames of them)");
  cmd.add_option("--fps", o.fps, "Frames per second of the animation: the simulation step is 1/FPS (default: scene dt)");
  cmd.add_option("--contact-sheet", o.contactSheet, "With --sequence: also a PNG of up to 12 frames, 4 per row");
}

double stepOfFps(double fps) {
  if (!(fps >= 1.0 && fps <= kMaxFps)) throw Error("--fps must be in [1, 1000]");
  return 1.0 / fps;
}

void checkSequence(std::uint32_t frames) {
  if (frames == 0 || frames > kMaxSequenceFrames)
    throw Error("--frames with --sequence must be in [1, " + std::to_string(kMaxSequenceFrames) +
                "] (frame_NNNN.png numbering); got " + std::to_string(frames));
}

void prepareSequenceOutputs(const SequenceOptions& o, const std::vector<CommandPath>& inputs) {
  prepareOutputFolder({"--sequence", o.dir}, inputs);
  if (!o.contactSheet.empty()) prepareOutputFile({"--contact-sheet", o.contactSheet}, inputs);
}

std::string sequenceFrameName(std::uint32_t frame) {
  char name[32];
  std::snprintf(name, sizeof(name), "frame_%04u.png", frame);
  return name;
}

void runSequence(const SequenceOptions& o, std::uint32_t frames, const RenderRequest& request, const HairAsset& asset,
                 const SceneOptions& scene, bool json, const nlohmann::json& guessed) {
  auto ctx = createContext(scene);
  const std::vector<std::uint32_t> sheetPicks = o.contactSheet.empty() ? std::vector<std::uint32_t>{}
                                                                        : sheetFrames(frames, kSheetTiles);
  std::vector<RgbaImage> sheet;
  RenderResult last;
  ProgressReporter progress("hairpipe render: sequence", frames, std::chrono::milliseconds(0));
  const auto start = std::chrono::steady_clock::now();
  const std::uint32_t done = renderSequence(*ctx, asset, request, frames, [&](std::uint32_t i, const RenderResult& image) {
    writePng(std::filesystem::path(o.dir) / sequenceFrameName(i), image.width, image.height, 4, image.rgba);
    if (std::find(sheetPicks.begin(), sheetPicks.end(), i) != sheetPicks.end())
      sheet.push_back({image.width, image.height, image.rgba});
    progress.update(i);
    last = image;
    return !interruptRequested();
  });
  progress.finish();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  checkValidation(*ctx);
  if (done < frames)
    throwIfInterrupted("after frame " + std::to_string(done) + " of " + std::to_string(frames) + ": " + o.dir +
                       " holds complete frames " + sequenceFrameName(1) + " to " + sequenceFrameName(done));
  if (!o.contactSheet.empty()) {
    const RgbaImage s = contactSheet(sheet, kSheetColumns);
    writePng(o.contactSheet, s.width, s.height, 4, s.pixels);
  }
  nlohmann::json r = report(o, frames, last, seconds, *ctx);
  if (!guessed.empty()) r["guessed"] = guessed;
  if (json) {
    std::cout << hp::jsonText(r) << "\n";
    return;
  }
  std::cout << "wrote " << frames << " frames " << o.dir << "/" << sequenceFrameName(1) << " .. "
            << sequenceFrameName(frames) << " (" << last.width << "x" << last.height << ", " << last.strands
            << " strands) on " << ctx->properties().deviceName << ", " << r["frames_per_second"].get<double>()
            << " frames/s\n";
  if (!o.contactSheet.empty()) std::cout << "wrote " << o.contactSheet << "\n";
}
}  // namespace hp::cli
