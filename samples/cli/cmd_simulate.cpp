// `hairpipe simulate`: runs N frames of the guide simulation on the device and reports, from a
// readback after the run, how well the constraints hold and what a frame costs on the GPU.
#include <bit>
#include <iostream>

#include <nlohmann/json.hpp>

#include "samples/tools/progress_reporter.h"
#include "samples/tools/simulation_driver.h"
#include "samples/tools/host/interaction_stats.h"
#include "engine/vk/transfer.h"
#include "engine/core/error.h"
#include "engine/core/hair/hair_export.h"
#include "engine/core/hair/hair_file.h"
#include "samples/cli/command.h"
#include "samples/cli/hair_grid_options.h"
#include "samples/cli/scene_options.h"
#include "samples/cli/output_paths.h"
#include "samples/tools/host/json_text.h"

namespace hp::cli::cmd_simulate {  // per subcommand: file-local names stay apart in a unity build

namespace {
struct SimulateOptions {
  hp::cli::SceneOptions scene;
  std::uint32_t frames = 120;
  std::optional<double> dt;
  std::optional<std::uint32_t> iterations;
  std::optional<std::uint32_t> substeps;
  hp::cli::HairGridOptions grid;
  std::string animate = "none";
  std::string out;
  bool json = false;
};

hp::SimulationParams simulationParams(const SimulateOptions& opt, hp::SimulationParams params) {
  if (opt.dt) params.dt = *opt.dt;
  if (opt.iterations) params.iterations = *opt.iterations;
  if (opt.substeps) params.substeps = *opt.substeps;
  hp::cli::applyHairGridOptions(opt.grid, params);
  params.validate();
  return params;
}

// The hair grid's report: where it is, whether it acted, the run's peak density against the target (rest-mean
// units) and its GPU ms a frame.
nlohmann::json gridReport(const hp::vk::Context& ctx, const hp::SimulatePass& pass, const hp::SimulationDriver& driver) {
  const hp::HairGridPass& grid = pass.grid();
  const hp::SimulationParams& p = pass.params();
  nlohmann::json r = {{"acts", p.gridActs()},
                      {"cells", {grid.layout().dims.x, grid.layout().dims.y, grid.layout().dims.z}},
                      {"cell_size", grid.layout().cellSize},
                      {"volume", p.volume},
                      {"volume_target", p.volumeTarget},
                      {"friction", p.friction}};
  if (!p.gridActs()) return r;
  const auto peak = hp::vk::readback<std::uint32_t>(ctx, grid.peak(), hp::vk::BufferUse::ComputeWrite, 1);
  r["peak_density"] = std::bit_cast<float>(peak[0]);
  r["gpu_ms_per_frame_median"] = driver.medianGridMilliseconds();
  return r;
}

// How the guides interact at the end of the run (samples/tools/host/interaction_stats.h): velocity spread in
// head-space cubes of the grid's cell size, and guides with roots within 1 cm coming closer than two pearl radii.
nlohmann::json interactionReport(const hp::SimulatePass& pass, const hp::SimulationDriver& driver,
                                 const std::vector<glm::vec4>& positions, const std::vector<glm::vec4>& previous) {
  const hp::SimulationParams& p = pass.params();
  const hp::VelocitySpread spread = hp::velocitySpreadInCells(positions, previous, pass.particlesPerGuide(), driver.head(),
                                                              pass.grid().layout().cellSize, p.dt / p.substeps);
  const hp::CloseParticles close = hp::closeNeighbourParticles(positions, pass.particlesPerGuide(), 0.01, 2.0 * p.pearlRadius);
  return {{"velocity_variance_in_cells", spread.withinCells},
          {"velocity_mean_square", spread.overall},
          {"close_neighbour_fraction", close.fraction}};
}

// The run's report (what --json prints): accuracy, cost, the hair layer, the grid and the interaction.
nlohmann::json simulateReport(const hp::vk::Context& ctx, const hp::SimulatePass& pass, const hp::SimulationDriver& driver,
                              const hp::HairAsset& asset, const std::vector<glm::vec4>& positions,
                              const std::vector<glm::vec4>& previous, std::uint32_t frames, hp::HeadAnimation animation) {
  const hp::SimStats stats = driver.stats(positions, previous);
  nlohmann::json report = {{"guides", pass.guideCount()},
                           {"particles_per_guide", pass.particlesPerGuide()},
                           {"frames", frames},
                           {"animation", hp::headAnimationName(animation)},
                           {"max_length_error", stats.maxLengthError},
                           {"min_collider_clearance", stats.minColliderClearance},
                           {"nan_count", stats.nanCount},
                           {"max_speed", stats.maxSpeed},
                           {"gpu_ms_per_frame_median", driver.medianFrameMilliseconds()},
                           {"device", ctx.properties().deviceName}};
  // The hair layer's thickness over the head (guide middles' distance from the head's surface), where the
  // asset has a distance field to measure it with.
  const hp::LayerThickness layer =
      asset.sdf ? hp::hairLayerThickness(positions, pass.particlesPerGuide(), *asset.sdf, driver.head())
                : hp::LayerThickness{};
  report["grid"] = gridReport(ctx, pass, driver);
  report["interaction"] = interactionReport(pass, driver, positions, previous);
  if (driver.characterVertices().size() > 0)  // a clip posed it
    report["character_gpu_ms_per_frame_median"] = driver.medianCharacterMilliseconds();
  if (asset.character) {
    const hp::CharacterMesh& m = *asset.character;
    std::vector<glm::vec3> posed = driver.characterVertices();  // as the last frame left it
    if (posed.empty()) posed = m.positions;
    const hp::MeshPenetration pen = hp::meshPenetration(positions, pass.particlesPerGuide(), posed, m.triangles, driver.head());
    report["mesh_penetration"] = {{"deepest", pen.deepest}, {"min_clearance", pen.minClearance},
                                  {"particles_inside", pen.inside}, {"particles", pen.particles}};
  }
  report["layer_thickness"] = layer.guides ? nlohmann::json{{"mean", layer.mean}, {"p90", layer.p90}, {"guides", layer.guides}}
                                           : nlohmann::json(nullptr);
  return report;
}

hp::GuideSet finalGuides(const std::vector<glm::vec4>& positions, std::uint32_t particlesPerGuide) {
  hp::GuideSet guides;
  guides.particlesPerGuide = particlesPerGuide;
  for (const auto& p : positions) guides.positions.emplace_back(p);
  return guides;
}

// The report as text.
void printReport(const nlohmann::json& r) {
  std::cout << "simulated " << r["frames"] << " frames of " << r["guides"] << " guides x " << r["particles_per_guide"]
            << " particles (" << r["animation"].get<std::string>() << ") on " << r["device"].get<std::string>() << "\n"
            << "  max_length_error        " << r["max_length_error"].get<double>() << "\n"
            << "  min_collider_clearance  " << r["min_collider_clearance"].get<double>() << "\n"
            << "  nan_count               " << r["nan_count"] << "\n"
            << "  max_speed               " << r["max_speed"].get<double>() << "\n"
            << "  gpu ms/frame (median)   " << r["gpu_ms_per_frame_median"].get<double>() << "\n";
  const auto& grid = r["grid"];
  if (grid["acts"].get<bool>())
    std::cout << "  hair grid               peak density " << grid["peak_density"].get<double>() << " (target "
              << grid["volume_target"].get<double>() << "), " << grid["gpu_ms_per_frame_median"].get<double>()
              << " gpu ms/frame\n";
  if (r.contains("mesh_penetration")) {
    const auto& m = r["mesh_penetration"];
    std::cout << "  character mesh          " << m["particles_inside"] << " of " << m["particles"]
              << " particles inside, deepest " << m["deepest"].get<double>() << "\n";
  }
  const auto& layer = r["layer_thickness"];
  if (!layer.is_null())
    std::cout << "  layer thickness         mean " << layer["mean"].get<double>() << ", 90th percentile "
              << layer["p90"].get<double>() << " (guide middles from the head's surface)\n";
}

void runSimulate(const SimulateOptions& opt) {
  if (opt.frames == 0 || opt.frames > 1000000) throw hp::Error("--frames must be in [1, 1000000]");
  hp::Scene scene = hp::cli::loadScene(opt.scene);
  hp::SimulationParams params = simulationParams(opt, scene.simulation);
  const std::optional<std::string> clipName = hp::clipOfAnimate(opt.animate);
  hp::HeadAnimation animation = clipName ? hp::HeadAnimation::None : hp::parseHeadAnimation(opt.animate);
  if (!opt.out.empty()) hp::cli::prepareOutputFile({"--out", opt.out}, hp::cli::sceneInputs(opt.scene, scene));
  hp::HairAsset asset = hp::buildSceneAsset(scene);
  auto ctx = hp::cli::createContext(opt.scene);
  const hp::CharacterClip clip = clipName ? hp::characterClip(asset, *clipName) : hp::CharacterClip{};
  hp::SimulatePass pass(*ctx, asset, params, glm::mat4(1.0f), nullptr, clip.clip ? hp::characterScalp(asset) : hp::ScalpInput{});
  hp::SimulationDriver driver(*ctx, pass, animation, hp::assetHeadRadius(asset));
  if (clip.clip) driver.setCharacterClip(clip);
  hp::ProgressReporter progress("hairpipe simulate", opt.frames);
  driver.runFrames(opt.frames, [&](std::uint32_t done) { progress.update(done); });
  progress.finish();
  const std::vector<glm::vec4> positions = driver.readPositions();  // the final state, read back once
  const std::vector<glm::vec4> previous = driver.readPrevious();
  hp::cli::checkValidation(*ctx);
  nlohmann::json report = simulateReport(*ctx, pass, driver, asset, positions, previous, opt.frames, animation);
  if (clip.clip) report["animation"] = opt.animate;
  if (opt.json) std::cout << hp::jsonText(report) << "\n";
  else printReport(report);
  // A diverged run is a failure, and its guides are not written: the report above says where it stood.
  const std::size_t nonFinite = report["nan_count"].get<std::size_t>();
  if (nonFinite > 0)
    throw hp::Error("the simulation diverged: " + std::to_string(nonFinite) + " of " + std::to_string(positions.size()) +
                    " particles are not finite" + (opt.out.empty() ? "" : "; " + opt.out + " was not written"));
  if (!opt.out.empty())
    hp::writeHairFile(opt.out, hp::guidesToHair(finalGuides(positions, pass.particlesPerGuide()),
                                                "hairpipe simulate: final guides"));
}

void setupSimulate(CLI::App& app) {
  auto opt = std::make_shared<SimulateOptions>();
  CLI::App* cmd = app.add_subcommand("simulate", "Run the guide simulation on the device and report its accuracy");
  hp::cli::addSceneOptions(*cmd, opt->scene);
  cmd->add_option("--frames", opt->frames, "Frames to simulate (default 120)");
  cmd->add_option("--dt", opt->dt, "Frame time step in seconds (overrides the scene)");
  cmd->add_option("--iterations", opt->iterations, "Constraint iterations per substep, 1..1000");
  cmd->add_option("--substeps", opt->substeps, "Substeps per frame, 1..64");
  hp::cli::addHairGridOptions(*cmd, opt->grid);
  cmd->add_option("--animate", opt->animate, "Head motion: none, nod, turn, shake or teleport, or clip:NAME (an animation clip of the --mesh character: its body is posed and collided with, the roots follow its bones)");
  cmd->add_option("--out", opt->out, "Write the final guides as .hair");
  cmd->add_flag("--json", opt->json, "Print JSON");
  cmd->callback([opt] { runSimulate(*opt); });
}
}  // namespace

HP_CLI_COMMAND(setupSimulate);
}  // namespace hp::cli::cmd_simulate
