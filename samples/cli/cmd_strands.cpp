// `hairpipe strands [--scene FILE | --model default|FILE.hair|FILE.obj] [--density N] [--vertices Q]
// [--guides-only] [--no-groom] [--clump ..] [--curl ..] [--frizz ..] --out FILE.hair [--json] [--device D]
// [--validation]`: builds the asset, uploads its rest-pose guides, runs tessellate + interpolate (with the
// scene's groom and the groom options) on the device once, reads the render strands
// back and writes them as .hair (Q points per strand), atomically. The dump itself is
// hp::compute::computeRenderStrands / renderStrandsToHairData (tools/strand_dump.h), which
// `hairpipe render --dump-strands` reuses.
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "samples/tools/strand_dump.h"
#include "engine/core/error.h"
#include "engine/core/hair/scene.h"
#include "engine/vk/context.h"
#include "samples/cli/groom_options.h"
#include "samples/cli/command.h"
#include "samples/cli/scene_options.h"
#include "shaders/shared/strands.h"
#include "samples/cli/output_paths.h"
#include "samples/tools/host/json_text.h"

namespace hp::cli::cmd_strands {  // per subcommand: file-local names stay apart in a unity build

namespace {
// Past this a dump is a mistake (2M x 36 vertices is already a 0.9 GB .hair file).
constexpr std::int64_t kMaxDensity = 2'000'000;

struct StrandsOptions {
  hp::cli::SceneOptions scene;
  hp::cli::GroomOptions groom;
  std::optional<std::int64_t> density;  // none: the scene's own density (a -1 sentinel let --density -1 through)
  std::int64_t vertices = hp::compute::kDefaultVerticesPerStrand;
  bool guidesOnly = false;
  std::string out;
  bool json = false;
};


void checkOptions(const StrandsOptions& o) {
  if (o.density && (*o.density < 1 || *o.density > kMaxDensity))
    throw hp::Error("--density must be in [1, " + std::to_string(kMaxDensity) + "] render strands, got " +
                    std::to_string(*o.density));
  if (o.vertices < 2 || o.vertices > hp::gpu::MAX_VERTICES_PER_STRAND)
    throw hp::Error("--vertices must be in [particles per guide, " + std::to_string(hp::gpu::MAX_VERTICES_PER_STRAND) +
                    "], got " + std::to_string(o.vertices));
}

double scopeMs(const hp::compute::StrandRun& run, const std::string& name) {
  for (const auto& t : run.times)
    if (t.name == name) return t.milliseconds;
  return 0.0;
}

void report(const StrandsOptions& o, const hp::HairAsset& asset, const hp::compute::StrandRun& run,
            const hp::vk::Context& ctx) {
  const hp::compute::StrandLayout& l = run.layout;
  nlohmann::json j = {{"out", o.out},
                      {"strands", l.strandCount},
                      {"vertices_per_strand", l.verticesPerStrand},
                      {"points", run.hair.pointCount()},
                      {"guides", l.guideCount},
                      {"particles_per_guide", l.particlesPerGuide},
                      {"triangles", asset.topology.triangles.size()},
                      {"guides_only", l.guidesOnly},
                      {"chunks", l.chunks.size()},
                      {"gpu_ms", {{"tessellate", scopeMs(run, "tessellate")}, {"interpolate", scopeMs(run, "interpolate")}}},
                      {"device", ctx.properties().deviceName}};
  if (o.json) {
    std::cout << hp::jsonText(j) << "\n";
    return;
  }
  std::cout << "wrote " << l.strandCount << (l.guidesOnly ? " smoothed guides" : " render strands") << " x "
            << l.verticesPerStrand << " vertices (from " << l.guideCount << " guides x " << l.particlesPerGuide
            << " particles, " << l.chunks.size() << (l.chunks.size() == 1 ? " chunk" : " chunks") << ") -> " << o.out
            << "\n";
}

void runStrands(const StrandsOptions& o) {
  checkOptions(o);
  hp::Scene scene = hp::cli::loadScene(o.scene);
  if (o.density) {
    scene.density.mode = hp::DensityOptions::Mode::Total;
    scene.density.totalStrands = static_cast<std::uint32_t>(*o.density);
  }
  hp::cli::prepareOutputFile({"--out", o.out}, hp::cli::sceneInputs(o.scene, scene));
  hp::cli::applyGroomOptions(o.groom, scene.groom);
  hp::HairAsset asset = hp::buildSceneAsset(scene);
  const std::uint32_t particles = asset.guides.particlesPerGuide;
  if (o.vertices < particles)
    throw hp::Error("--vertices must be at least the particles per guide (" + std::to_string(particles) + "), got " +
                    std::to_string(o.vertices));
  auto ctx = hp::cli::createContext(o.scene);
  hp::compute::StrandOptions options;
  options.verticesPerStrand = static_cast<std::uint32_t>(o.vertices);
  options.guidesOnly = o.guidesOnly;
  const std::string info = std::string("hairpipe strands ") + (o.guidesOnly ? "guides-only " : "") +
                           std::to_string(o.vertices) + " vertices: " + scene.source;
  hp::compute::StrandRun run = hp::compute::computeRenderStrands(*ctx, asset, options, info, scene.groom);
  hp::cli::checkValidation(*ctx);
  hp::writeHairFile(o.out, run.hair);
  report(o, asset, run, *ctx);
}

void setupStrands(CLI::App& app) {
  auto o = std::make_shared<StrandsOptions>();
  CLI::App* cmd = app.add_subcommand(
      "strands", "Tessellate and interpolate the hair on the device and write the render strands as .hair");
  hp::cli::addSceneOptions(*cmd, o->scene);
  cmd->add_option("--density", o->density, "Render strands in total (overrides the scene), 1-2000000");
  cmd->add_option("--vertices", o->vertices, "Vertices per smoothed strand (Q), particles per guide to 256")
      ->capture_default_str();
  cmd->add_flag("--guides-only", o->guidesOnly, "Debug: write the smoothed guides (one strand per guide), no interpolation");
  hp::cli::addGroomOptions(*cmd, o->groom);
  cmd->add_option("--out", o->out, "Output .hair file (written atomically)")->required();
  cmd->add_flag("--json", o->json, "Print a JSON report");
  cmd->callback([o] { runStrands(*o); });
}
}  // namespace

HP_CLI_COMMAND(setupStrands);
}  // namespace hp::cli::cmd_strands
