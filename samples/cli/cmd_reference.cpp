// `hairpipe reference`: the ground truth of a frame, path traced on the CPU (samples/tools/reference/):
// the same render strands (simulated, tessellated and interpolated on the device, read back), head,
// camera, light, fibre model and exposure as `hairpipe render` with the same options draws, or the
// frame of an export folder (--frame DIR, from `render --export-frame`). Writes linear radiance (.pfm)
// or the tonemapped image (.png, the render command's display curve), atomically.
#include <iostream>
#include <set>

#include <nlohmann/json.hpp>

#include "engine/core/error.h"
#include "samples/cli/command.h"
#include "samples/tools/interrupt_flag.h"
#include "samples/cli/frame_options.h"
#include "samples/cli/output_paths.h"
#include "samples/tools/frame_export.h"
#include "samples/tools/host/memory_estimate.h"
#include "samples/tools/png_file.h"
#include "samples/tools/reference/fibre.h"
#include "samples/tools/reference/path_tracer.h"
#include "samples/tools/host/json_text.h"

namespace hp::cli::cmd_reference {  // per subcommand: file-local names stay apart in a unity build

namespace {
struct ReferenceOptions {
  hp::cli::FrameOptions frame;
  std::string frameDir;
  std::string out = "out/reference.png";
  hp::reference::TraceSettings trace;
  bool quiet = false;
  bool json = false;
  double maxMemoryGiB = 0.0;  // 0: what the machine has available
};

std::uint64_t memoryLimit(const ReferenceOptions& o) {
  if (!(o.maxMemoryGiB >= 0.0) || o.maxMemoryGiB > 1e6) throw hp::Error("--max-memory must be in [0, 1e6] GiB");
  return std::uint64_t(o.maxMemoryGiB * double(1ull << 30));
}

bool isPfm(const std::filesystem::path& p) { return p.extension() == ".pfm"; }

// --frame DIR describes the whole frame: any frame option given with it is refused, by name.
void refuseFrameOptionsWithFrameDir(const CLI::App& cmd) {
  static const std::set<std::string> own = {"--frame", "--out", "--spp", "--bounces", "--seed", "--threads", "--quiet",
                                            "--json", "--max-memory", "--help"};
  for (const CLI::Option* opt : cmd.get_options())
    if (opt->count() > 0 && !own.count(opt->get_name())) throw hp::Error(opt->get_name() + " cannot be combined with --frame (the export folder holds the whole frame)");
}

// The frame from the device: render it as `hairpipe render` would and keep what was drawn.
hp::ExportedFrame frameFromDevice(const ReferenceOptions& o, const CLI::App& cmd) {
  hp::RenderRequest request = hp::cli::makeRenderRequest(o.frame, cmd);
  request.captureFrame = true;
  // The images alone, before the device renders anything (the strands are counted again before the trace).
  hp::requireHostMemory("reference at " + std::to_string(request.scene.render.width) + "x" +
                            std::to_string(request.scene.render.height),
                        hp::referenceHostBytes(request.scene.render.width, request.scene.render.height, 0),
                        memoryLimit(o));
  hp::cli::prepareOutputFile({"--out", o.out}, hp::cli::sceneInputs(o.frame.scene, request.scene));
  hp::HairAsset asset = hp::buildSceneAsset(request.scene);
  hp::cli::frameCamera(request.scene, asset);
  auto ctx = hp::cli::createContext(o.frame.scene);
  hp::RenderResult result = hp::renderStill(*ctx, asset, request);
  hp::cli::checkValidation(*ctx);
  return hp::makeExportedFrame(request, asset, *result.frame,
                               hp::reference::fibreModelName(hp::reference::fibreModelOf(request.lutMode)));
}

void runReference(const ReferenceOptions& o, const CLI::App& cmd) {
  const std::filesystem::path out = o.out;
  if (!isPfm(out) && out.extension() != ".png") throw hp::Error("--out must end in .pfm (linear radiance) or .png");
  o.trace.validate();
  hp::ExportedFrame frame;
  if (!o.frameDir.empty()) {
    refuseFrameOptionsWithFrameDir(cmd);
    hp::cli::prepareOutputFile({"--out", o.out}, {{"--frame", o.frameDir}});
    frame = hp::readFrameExport(o.frameDir);
  } else {
    frame = frameFromDevice(o, cmd);
  }
  const std::uint64_t estimate =
      hp::referenceHostBytes(frame.camera.width, frame.camera.height, frame.strands.points.size());
  hp::requireHostMemory("reference at " + std::to_string(frame.camera.width) + "x" + std::to_string(frame.camera.height),
                        estimate, memoryLimit(o));
  if (!o.quiet && estimate > (1ull << 30))
    std::cerr << "reference: about " << hp::gibibytes(estimate) << " of host memory for the images and the scene\n";
  hp::reference::TraceSettings settings = o.trace;
  settings.progress = o.quiet ? nullptr : &std::cerr;
  settings.stop = hp::interruptRequested;
  hp::throwIfInterrupted("before the trace: nothing written");
  hp::reference::TraceResult r;
  try {
    r = hp::reference::traceReference(frame, settings);
  } catch (const hp::Error&) {
    hp::throwIfInterrupted("during the trace: nothing written");  // the signal, not the stop, is the news
    throw;
  }
  if (isPfm(out)) hp::writePfm(out, r.radiance);
  else hp::writePng(out, r.radiance.width, r.radiance.height, 4, hp::displayRgba8(r.radiance, frame.exposure));
  const nlohmann::json report = {{"out", o.out}, {"width", r.radiance.width}, {"height", r.radiance.height},
                                 {"spp", settings.spp}, {"bounces", settings.bounces}, {"seed", settings.seed},
                                 {"threads", r.threads}, {"seconds", r.seconds}, {"paths", r.paths},
                                 {"fibre_model", frame.fibreModel}, {"strands", frame.strands.strandCount}};
  if (o.json) {
    std::cout << hp::jsonText(report) << "\n";
    return;
  }
  std::cout << "wrote " << o.out << " (" << r.radiance.width << "x" << r.radiance.height << ", " << settings.spp
            << " spp, " << settings.bounces << " bounces, seed " << settings.seed << ", " << frame.strands.strandCount
            << " strands, " << frame.fibreModel << " fibres) in " << r.seconds << " s on " << r.threads << " threads\n";
}

void setupReference(CLI::App& app) {
  auto o = std::make_shared<ReferenceOptions>();
  CLI::App* cmd = app.add_subcommand("reference", "Path-trace the ground truth of a frame on the CPU (Embree)");
  hp::cli::addFrameOptions(*cmd, o->frame);
  cmd->add_option("--frame", o->frameDir, "Trace an exported frame (render --export-frame DIR) instead of the scene options");
  cmd->add_option("--out", o->out, "Output: .pfm (linear radiance) or .png (tonemapped like render; default out/reference.png)");
  cmd->add_option("--spp", o->trace.spp, "Camera samples per pixel (default 64)");
  cmd->add_option("--bounces", o->trace.bounces, "Scattering events per path, >= 1 (default 8; 1: single scattering)");
  cmd->add_option("--seed", o->trace.seed, "Random seed; the image is the same for a seed on any thread count (default 1)");
  cmd->add_option("--threads", o->trace.threads, "Worker threads (default 0: all hardware threads)");
  cmd->add_flag("--quiet", o->quiet, "No progress lines on stderr");
  cmd->add_option("--max-memory", o->maxMemoryGiB,
                  "Refuse a run whose host memory estimate exceeds this many GiB (default: what is available)");
  cmd->add_flag("--json", o->json, "Print JSON");
  cmd->callback([o, cmd] { runReference(*o, *cmd); });
}
}  // namespace

HP_CLI_COMMAND(setupReference);
}  // namespace hp::cli::cmd_reference
