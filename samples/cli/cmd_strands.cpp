// `hairpipe strands [--scene FILE | --model default|FILE.hair|FILE.obj] [--density N] [--vertices Q]
// [--guides-only] --out FILE.hair [--json] [--device D] [--validation]`: builds the asset, uploads
// its rest-pose guides, runs tessellate + interpolate on the device once, reads the render strands
// back and writes them as .hair (Q points per strand), atomically. The dump itself is
// hp::compute::computeRenderStrands / renderStrandsToHairData (compute/strand_dump.h), which
// `hairpipe render --dump-strands` reuses.
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <string>

#include <nlohmann/json.hpp>

#include "compute/strand_dump.h"
#include "engine/error.h"
#include "engine/hair/scene.h"
#include "engine/vk/context.h"
#include "samples/cli/command.h"
#include "shaders/shared/strands.h"

namespace {
// Past this a dump is a mistake (2M x 36 vertices is already a 0.9 GB .hair file).
constexpr std::int64_t kMaxDensity = 2'000'000;

struct StrandsOptions {
  std::string scene;
  std::string model = "default";
  std::int64_t density = -1;  // -1: the scene's own density
  std::int64_t vertices = hp::compute::kDefaultVerticesPerStrand;
  bool guidesOnly = false;
  std::string out;
  bool json = false;
  std::string device;
  bool validation = false;
};

hp::Scene loadScene(const StrandsOptions& o) {
  if (!o.scene.empty()) return hp::loadSceneFile(o.scene);
  hp::Scene scene;
  if (o.model == "default") return scene;
  const std::filesystem::path path(o.model);
  const std::string ext = path.extension().string();
  if (ext == ".hair")
    scene.model.kind = hp::ModelSpec::Kind::Hair;
  else if (ext == ".obj")
    scene.model.kind = hp::ModelSpec::Kind::Obj;
  else
    throw hp::Error("--model " + o.model + ": expected 'default', a .hair file or an .obj file");
  scene.model.path = path;
  scene.source = o.model;
  return scene;
}

void checkOptions(const StrandsOptions& o) {
  if (o.density != -1 && (o.density < 1 || o.density > kMaxDensity))
    throw hp::Error("--density must be in [1, " + std::to_string(kMaxDensity) + "] render strands, got " +
                    std::to_string(o.density));
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
    std::cout << j.dump(2) << "\n";
    return;
  }
  std::cout << "wrote " << l.strandCount << (l.guidesOnly ? " smoothed guides" : " render strands") << " x "
            << l.verticesPerStrand << " vertices (from " << l.guideCount << " guides x " << l.particlesPerGuide
            << " particles, " << l.chunks.size() << (l.chunks.size() == 1 ? " chunk" : " chunks") << ") -> " << o.out
            << "\n";
}

void runStrands(const StrandsOptions& o) {
  checkOptions(o);
  hp::Scene scene = loadScene(o);
  if (o.density != -1) {
    scene.density.mode = hp::DensityOptions::Mode::Total;
    scene.density.totalStrands = static_cast<std::uint32_t>(o.density);
  }
  hp::HairAsset asset = hp::buildSceneAsset(scene);
  const std::uint32_t particles = asset.guides.particlesPerGuide;
  if (o.vertices < particles)
    throw hp::Error("--vertices must be at least the particles per guide (" + std::to_string(particles) + "), got " +
                    std::to_string(o.vertices));
  hp::vk::ContextOptions ctxOptions;
  ctxOptions.device = o.device;
  ctxOptions.validation = o.validation;
  auto ctx = hp::vk::Context::createHeadless(ctxOptions);
  ctx->validationLog().setEcho(true);
  hp::compute::StrandOptions options;
  options.verticesPerStrand = static_cast<std::uint32_t>(o.vertices);
  options.guidesOnly = o.guidesOnly;
  const std::string info = std::string("hairpipe strands ") + (o.guidesOnly ? "guides-only " : "") +
                           std::to_string(o.vertices) + " vertices: " + scene.source;
  hp::compute::StrandRun run = hp::compute::computeRenderStrands(*ctx, asset, options, info);
  if (ctx->validationEnabled() && ctx->validationLog().problemCount() > 0)
    throw hp::Error(std::to_string(ctx->validationLog().problemCount()) + " Vulkan validation message(s) were reported");
  hp::writeHairFile(o.out, run.hair);
  report(o, asset, run, *ctx);
}

void setupStrands(CLI::App& app) {
  auto o = std::make_shared<StrandsOptions>();
  CLI::App* cmd = app.add_subcommand(
      "strands", "Tessellate and interpolate the hair on the device and write the render strands as .hair");
  auto* scene = cmd->add_option("--scene", o->scene, "Scene file (JSON; schema in engine/hair/README.md)");
  cmd->add_option("--model", o->model, "Model when no scene is given: default, FILE.hair or FILE.obj")->excludes(scene);
  cmd->add_option("--density", o->density, "Render strands in total (overrides the scene), 1-2000000");
  cmd->add_option("--vertices", o->vertices, "Vertices per smoothed strand (Q), particles per guide to 256")
      ->capture_default_str();
  cmd->add_flag("--guides-only", o->guidesOnly, "Debug: write the smoothed guides (one strand per guide), no interpolation");
  cmd->add_option("--out", o->out, "Output .hair file (written atomically)")->required();
  cmd->add_flag("--json", o->json, "Print a JSON report");
  cmd->add_option("--device", o->device, "Vulkan device: index or name substring (env HAIRPIPE_DEVICE)");
  cmd->add_flag("--validation", o->validation, "Run with the Khronos validation layer; fail on any message");
  cmd->callback([o] { runStrands(*o); });
}
}  // namespace

HP_CLI_COMMAND(setupStrands);
