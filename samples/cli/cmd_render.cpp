// `hairpipe render`: simulates N frames so the hair settles, renders the last one (head + hair with
// Marschner shading, opacity shadow maps), writes the PNG atomically and prints the GPU time of every
// pass. --dump-opacity DIR also writes the 16 opacity slices (PFM), a contact sheet (PNG) and the
// slice depths (JSON); --export-frame DIR writes the frame for an offline renderer (frame_export.h);
// --sequence DIR renders every frame of the animation instead (render_sequence.h).
#include <algorithm>
#include <cmath>
#include <iostream>

#include <nlohmann/json.hpp>

#include "engine/core/error.h"
#include "samples/tools/host/camera_fit.h"
#include "samples/tools/png_file.h"
#include "samples/tools/progress_reporter.h"
#include "samples/tools/render_job.h"
#include "samples/cli/render_sequence.h"
#include "samples/cli/command.h"
#include "samples/cli/frame_options.h"
#include "samples/tools/frame_export.h"
#include "samples/tools/reference/fibre.h"
#include "samples/cli/output_paths.h"
#include "samples/tools/host/json_text.h"

namespace hp::cli::cmd_render {  // per subcommand: file-local names stay apart in a unity build

namespace {
struct RenderOptions {
  hp::cli::FrameOptions frame;
  std::string out = "out/hair.png";
  bool json = false;
  std::string dumpOpacity;
  std::string dumpStrands;
  std::string exportFrame;
  bool motionVectors = false;
  hp::cli::SequenceOptions sequence;
};

// Every output checked (not an input, folder writable) before the simulation starts.
void prepareOutputs(const RenderOptions& o, const hp::Scene& scene) {
  const std::vector<hp::cli::CommandPath> inputs = hp::cli::sceneInputs(o.frame.scene, scene);
  hp::cli::prepareOutputFile({"--out", o.out}, inputs);
  if (!o.dumpStrands.empty()) hp::cli::prepareOutputFile({"--dump-strands", o.dumpStrands}, inputs);
  if (!o.dumpOpacity.empty()) hp::cli::prepareOutputFolder({"--dump-opacity", o.dumpOpacity}, inputs);
  if (!o.exportFrame.empty())
    hp::cli::prepareOutputFolder({"--export-frame", o.exportFrame}, inputs, hp::FrameExportFiles::all());
}

// The frame's files and the real-time image (linear radiance before exposure, hair coverage).
void exportFrame(const std::filesystem::path& dir, const hp::RenderRequest& request, const hp::HairAsset& asset,
                 const hp::FrameCapture& frame) {
  const hp::ExportedFrame exported = hp::makeExportedFrame(
      request, asset, frame, hp::reference::fibreModelName(hp::reference::fibreModelOf(request.lutMode)));
  hp::writeFrameExport(dir, exported);
  hp::writePfm(dir / hp::FrameExportFiles::realtime, frame.linear);
  if (frame.hairAlpha.width > 0) hp::writePfm(dir / hp::FrameExportFiles::realtimeHairAlpha, frame.hairAlpha);
  if (frame.motion.width > 0) hp::writePfm(dir / hp::FrameExportFiles::realtimeMotion, frame.motion);
}

void runRender(const RenderOptions& o, const CLI::App& cmd) {
  hp::RenderRequest request = hp::cli::makeRenderRequest(o.frame, cmd);
  if (o.sequence.fps) request.scene.simulation.dt = hp::cli::stepOfFps(*o.sequence.fps);
  if (!o.sequence.dir.empty()) {
    if (cmd.count("--out") || !o.dumpOpacity.empty() || !o.dumpStrands.empty() || !o.exportFrame.empty() ||
        o.motionVectors)
      throw hp::Error("--sequence writes DIR/frame_NNNN.png: --out, the dumps, --export-frame and --motion-vectors "
                      "do not apply");
    hp::cli::checkSequence(o.frame.frames);
    hp::cli::prepareSequenceOutputs(o.sequence, hp::cli::sceneInputs(o.frame.scene, request.scene));
    hp::HairAsset asset = hp::buildSceneAsset(request.scene);
    const nlohmann::json guessed = hp::cli::frameCamera(request.scene, asset);
    request.settleFrames = 0;  // the sequence is the animation from its first step
    hp::cli::runSequence(o.sequence, o.frame.frames, request, asset, o.frame.scene, o.json, guessed);
    return;
  }
  if (!o.sequence.contactSheet.empty()) throw hp::Error("--contact-sheet needs --sequence DIR");
  if (!o.dumpOpacity.empty() && !request.opacity.enabled)
    throw hp::Error("--dump-opacity needs opacity shadows (drop --no-shadows)");
  const auto casts = [](const hp::LightSpec& l) { return l.shadows; };
  const std::vector<hp::LightSpec> lights = hp::frameLights(request);  // the environment's lights too
  if (!o.dumpOpacity.empty() && std::none_of(lights.begin(), lights.end(), casts))
    throw hp::Error("--dump-opacity needs a light that casts shadows (shadows=on)");
  request.captureOpacity = !o.dumpOpacity.empty();
  request.captureStrands = !o.dumpStrands.empty();
  request.captureFrame = !o.exportFrame.empty();
  if (o.motionVectors && o.exportFrame.empty())
    throw hp::Error("--motion-vectors writes realtime_motion.pfm into the --export-frame folder: give --export-frame DIR");
  request.motionVectors = o.motionVectors;
  prepareOutputs(o, request.scene);
  hp::HairAsset asset = hp::buildSceneAsset(request.scene);
  const nlohmann::json guessed = hp::cli::frameCamera(request.scene, asset);
  auto ctx = hp::cli::createContext(o.frame.scene);
  hp::ProgressReporter progress("hairpipe render: settling", request.settleFrames);
  hp::RenderResult result = hp::renderStill(*ctx, asset, request, [&](std::uint32_t done) { progress.update(done); });
  progress.finish();
  hp::cli::checkValidation(*ctx);
  // The outputs that check what they encode (a non-finite strand is refused) go first, the image last: a run
  // that fails leaves no image beside a missing export.
  if (result.frame) exportFrame(o.exportFrame, request, asset, *result.frame);
  if (result.strandDump) hp::writeHairFile(o.dumpStrands, *result.strandDump);
  if (result.opacity) hp::render::writeOpacityDump(o.dumpOpacity, *result.opacity);
  hp::writePng(o.out, result.width, result.height, 4, result.rgba);
  nlohmann::json passes = nlohmann::json::object();
  for (const auto& t : result.passTimes) passes[t.name] = t.milliseconds;
  nlohmann::json report = {{"out", o.out},        {"width", result.width},   {"height", result.height},
                           {"guides", result.guides}, {"strands", result.strands},
                           {"vertices_per_strand", result.verticesPerStrand},
                           {"lut_mode", o.frame.lutMode}, {"device", ctx->properties().deviceName},
                           {"gpu_ms", passes}, {"raster", hp::rasterModeName(result.raster)},
                           {"opacity_raster", hp::render::opacityRasterName(result.opacityRaster)}};
  if (!guessed.empty()) report["guessed"] = guessed;
  if (result.rasterStats) {
    const auto& s = *result.rasterStats;
    report["raster_lists"] = {{"requested", s.requested}, {"kept", s.kept},
                              {"dropped_tile_budget", s.droppedByTileBudget},
                              {"dropped_capacity", s.droppedByCapacity}, {"overflow", s.overflow()},
                              {"shaded_vertices", s.shaded}};
  }
  if (result.opacity) report["opacity_dump"] = o.dumpOpacity;
  if (result.strandDump) report["strands_dump"] = o.dumpStrands;
  if (result.frame) report["export_frame"] = o.exportFrame;
  if (o.json) {
    std::cout << hp::jsonText(report) << "\n";
    return;
  }
  std::cout << "wrote " << o.out << " (" << result.width << "x" << result.height << ", " << result.strands
            << " strands from " << result.guides << " guides) on " << ctx->properties().deviceName << "\n";
  std::cout << "  raster: " << hp::rasterModeName(result.raster)
            << ", opacity maps: " << hp::render::opacityRasterName(result.opacityRaster) << "\n";
  if (result.rasterStats)
    std::cout << "  tile lists: " << result.rasterStats->kept << " entries kept of " << result.rasterStats->requested
              << ", overflow " << result.rasterStats->overflow() << " (tile budget "
              << result.rasterStats->droppedByTileBudget << ", capacity " << result.rasterStats->droppedByCapacity
              << "), " << result.rasterStats->shaded << " vertices shaded\n";
  for (const auto& t : result.passTimes) std::cout << "  " << t.name << ": " << t.milliseconds << " ms\n";
}

void setupRender(CLI::App& app) {
  auto o = std::make_shared<RenderOptions>();
  CLI::App* cmd = app.add_subcommand("render", "Simulate, then render the last frame to a PNG");
  hp::cli::addFrameOptions(*cmd, o->frame);
  cmd->add_option("--dump-strands", o->dumpStrands, "Write the rendered frame's render strands as .hair (Q points each)");
  cmd->add_option("--dump-opacity", o->dumpOpacity, "Write the 16 opacity slices (PFM), a contact sheet and the slice depths to DIR");
  cmd->add_option("--export-frame", o->exportFrame,
                  "Write the frame for an offline renderer to DIR: strands.hair, head.obj, frame.json "
                  "(docs/FRAME_EXPORT.md), and the real-time image as realtime.pfm + realtime_hair_alpha.pfm");
  cmd->add_flag("--motion-vectors", o->motionVectors,
                "With --export-frame (compute raster): also the hair's screen motion of the frame's own simulation "
                "step, realtime_motion.pfm (x, y pixels, current minus previous; coverage-weighted)");
  cmd->add_option("--out", o->out, "Output PNG (default out/hair.png)");
  hp::cli::addSequenceOptions(*cmd, o->sequence);
  cmd->add_flag("--json", o->json, "Print JSON");
  cmd->callback([o, cmd] { runRender(*o, *cmd); });
}
}  // namespace

HP_CLI_COMMAND(setupRender);
}  // namespace hp::cli::cmd_render
