// `hairpipe bench [--strands LIST] [--resolution WxH] [--frames N] [--raster LIST] [--msaa LIST]
// [--skin-bounce off,on] [--skin-indirect off,on] [--scattering single,dual] [--lut-mode LIST] [--groom scene,none] [material options] [--json F]
// [--plot F.svg] [--scene F | --model F [--units U] [--up A] [--mesh F]] [--own-strands]`: the whole frame on the
// default head, or the scene or model (bench_frame.h), for each strand count and raster
// path (once per --msaa value: the head's samples, and the graphics path's hair samples; once per fibre model
// and scattering), after one warm-up frame: per pass the GPU-timestamp median (min/max) of N frames, the
// frame total, each compute pass's achieved bytes/s as a fraction of a vkCmdCopyBuffer timed in the same frames, the host time and resident-memory growth per frame, the
// device and driver. --json writes the report to F, --plot an SVG of ms per pass against strand count.
// Suites over other axes are its subcommands (bench_context.h): `bench strands` (tessellate/interpolate
// to 1M strands), `bench opacity` (map sizes), `bench sim` (guide counts), `bench instances` (heads per
// Renderer), `bench head` and `bench assets` (host work).
#include <algorithm>
#include <charconv>
#include <cstdio>
#include <iostream>
#include <string_view>

#include <nlohmann/json.hpp>

#include "engine/core/error.h"
#include "engine/core/number_text.h"
#include "engine/core/hair/atomic_write.h"
#include "engine/core/hair/input_file.h"
#include "samples/tools/copy_reference.h"
#include "samples/cli/bench_context.h"
#include "samples/cli/bench_frame.h"
#include "samples/tools/interrupt_flag.h"
#include "samples/cli/bench_plot.h"
#include "samples/cli/command.h"
#include "samples/cli/material_options.h"
#include "samples/cli/output_paths.h"
#include "samples/cli/scene_options.h"
#include "samples/tools/host/json_text.h"

namespace hp::cli::cmd_bench {  // per subcommand: file-local names stay apart in a unity build

namespace {
struct BenchOptions {
  std::vector<std::uint32_t> strands{20000};
  std::string resolution = "640x480";
  std::uint32_t frames = 3;
  std::vector<std::string> raster{"compute", "graphics"};
  std::vector<std::uint32_t> msaa{4};
  std::string opacityRaster = "auto";
  std::vector<std::string> skinBounce{"on"};
  std::vector<std::string> skinIndirect{"on"};
  std::vector<std::string> scattering{hp::render::scatteringName(hp::render::LookSettings{}.scattering)};
  std::vector<std::string> lutModes{hp::lutModeName(hp::cli::FrameCase{}.lutMode)};
  std::vector<float> lodFractions{1.0f};
  std::vector<std::uint32_t> lights{1};
  std::vector<std::uint32_t> bounceSamples{hp::gpu::RENDER_BOUNCE_STRAND_SAMPLES};
  std::vector<std::string> fineWalks{"auto"};
  std::vector<std::string> grooms{"scene"};
  std::vector<std::uint32_t> shadowStrands{hp::render::OpacitySettings{}.shadowStrands};
  std::vector<float> shadingSpacings{hp::compute::RasterSettings{}.shadingSpacing};
  std::vector<std::string> growLists{"off"};
  hp::HairMaterial material;  // every case's (the material options; else the scene's)
  bool materialGiven = false;
  hp::cli::SceneOptions scene;  // --scene / --model (its --device and --validation unused: bench's own)
  bool ownStrands = false;
  std::string json, plot, device;
};

// WxH, each a plain decimal in [1, 16384] (sscanf's %u wrapped 4294967328 to 32 and read -5 as huge).
void parseResolution(const std::string& text, std::uint32_t& w, std::uint32_t& h) {
  const auto side = [&](std::string_view part, std::uint32_t& out) {
    const auto [end, ec] = std::from_chars(part.data(), part.data() + part.size(), out);
    return ec == std::errc() && end == part.data() + part.size() && out >= 1 && out <= 16384;
  };
  const std::size_t x = text.find('x');
  if (x == std::string::npos || !side(std::string_view(text).substr(0, x), w) ||
      !side(std::string_view(text).substr(x + 1), h))
    throw hp::Error("bench: --resolution must be WxH with each in [1, 16384], got '" + hp::excerpt(text) + "'");
}

// A list option whose values are one of two words: true where a value is `yes`; anything else refused by name
// ("bench: --groom takes scene and/or none, got 'curly'").
std::vector<bool> twoWordList(const char* option, const std::vector<std::string>& values, const std::string& first,
                              const std::string& second, const std::string& yes) {
  std::vector<bool> out;
  for (const std::string& v : values) {
    if (v != first && v != second)
      throw hp::Error(std::string("bench: ") + option + " takes " + first + " and/or " + second + ", got '" +
                      v.substr(0, 40) + "'");
    out.push_back(v == yes);
  }
  return out;
}

// c once for each --msaa, --lod-fraction, --lights, --bounce-samples, groom (true: the scene's), skin indirect
// light and --shadow-strands.
void addSampleCounts(hp::cli::FrameCase c, const BenchOptions& o, const std::vector<bool>& grooms,
                     const std::vector<bool>& indirects, std::vector<hp::cli::FrameCase>& out) {
  for (std::uint32_t m : o.msaa)
    for (float f : o.lodFractions)
      for (std::uint32_t lights : o.lights)
        for (std::uint32_t bounce : o.bounceSamples)
          for (const bool groom : grooms)
            for (const bool indirect : indirects)
              for (std::uint32_t shadowStrands : o.shadowStrands) {
                c.msaa = m;
                c.lodFraction = f;
                c.lights = lights;
                c.bounceSamples = bounce;
                c.groom = groom;
                c.skinIndirect = indirect;
                c.shadowStrands = shadowStrands;
                out.push_back(c);
              }
}

// A parser's error, prefixed with the option it came from.
template <class F>
auto named(const char* option, F&& parse) {
  try {
    return parse();
  } catch (const hp::Error& e) {
    throw hp::Error(std::string("bench: ") + option + ": " + e.what());
  }
}

// Each --lut-mode with each --scattering; dual needs the physical model, so the other models get single
// scattering once.
std::vector<std::pair<hp::LutMode, hp::render::Scattering>> shadings(const BenchOptions& o) {
  std::vector<std::pair<hp::LutMode, hp::render::Scattering>> out;
  for (const std::string& m : o.lutModes) {
    const hp::LutMode lut = named("--lut-mode", [&] { return hp::parseLutMode(m); });
    for (const std::string& s : o.scattering) {
      hp::render::Scattering scattering = named("--scattering", [&] { return hp::render::parseScattering(s); });
      if (lut != hp::LutMode::Physical) scattering = hp::render::Scattering::Single;
      if (std::find(out.begin(), out.end(), std::pair{lut, scattering}) == out.end()) out.emplace_back(lut, scattering);
    }
  }
  return out;
}

// --fine-walk as values (the compute path's).
std::vector<hp::compute::FineWalk> fineWalks(const BenchOptions& o) {
  std::vector<hp::compute::FineWalk> out;
  for (const std::string& w : o.fineWalks) {
    const std::optional<hp::compute::FineWalk> walk = hp::compute::parseFineWalk(w);
    if (!walk) throw hp::Error("bench: --fine-walk takes auto, direct and/or staged, got '" + w.substr(0, 40) + "'");
    out.push_back(*walk);
  }
  return out;
}

// Every numeric option in its range (before any model is read).
void checkRanges(const BenchOptions& o) {
  if (o.frames == 0 || o.frames > 1000) throw hp::Error("bench: --frames must be in [1, 1000]");
  for (std::uint32_t m : o.msaa)
    if (m != 1 && m != 2 && m != 4 && m != 8) throw hp::Error("bench: --msaa values must be 1, 2, 4 or 8, got " + std::to_string(m));
  for (float f : o.lodFractions)
    if (!(f >= hp::kMinLodFraction && f <= 1.0f))
      throw hp::Error("bench: --lod-fraction values must be in [" + hp::numberText(hp::kMinLodFraction) + ", 1], got " +
                      hp::numberText(f));
  for (std::uint32_t n : o.lights)
    if (n < 1 || n > 4) throw hp::Error("bench: --lights values must be in [1, 4], got " + std::to_string(n));
  for (std::uint32_t n : o.bounceSamples)
    if (n < 2 || n > hp::gpu::MAX_VERTICES_PER_STRAND)
      throw hp::Error("bench: --bounce-samples values must be in [2, " + std::to_string(hp::gpu::MAX_VERTICES_PER_STRAND) +
                      "], got " + std::to_string(n));
  for (float f : o.shadingSpacings)
    if (!(f >= 0.0f && f <= hp::compute::kMaxShadingSpacing))
      throw hp::Error("bench: --shading-spacing values must be in [0, " +
                      std::to_string(int(hp::compute::kMaxShadingSpacing)) + "] pixels, got " + std::to_string(f));
  for (std::uint32_t s : o.strands)
    if (!o.ownStrands && (s == 0 || s > 4'000'000)) throw hp::Error("bench: --strands values must be in [1, 4000000]");
}

std::vector<hp::cli::FrameCase> cases(const BenchOptions& o, const std::shared_ptr<const hp::Scene>& scene) {
  checkRanges(o);
  hp::cli::FrameCase base;
  base.ownStrands = o.ownStrands;
  base.frames = o.frames;
  base.material = o.materialGiven ? o.material : scene->material;
  parseResolution(o.resolution, base.width, base.height);
  base.opacityRaster = hp::render::parseOpacityRaster(o.opacityRaster);
  const auto shadingList = shadings(o);
  // --skin-bounce is the compute path's; the graphics path keeps FrameCase's default.
  const std::vector<bool> computeBounces = twoWordList("--skin-bounce", o.skinBounce, "off", "on", "on"),
                          graphicsBounces{base.skinBounce};
  const std::vector<bool> grooms = twoWordList("--groom", o.grooms, "scene", "none", "scene");
  const std::vector<bool> indirects = twoWordList("--skin-indirect", o.skinIndirect, "off", "on", "on");
  const std::vector<hp::compute::FineWalk> computeWalks = fineWalks(o), graphicsWalks{base.fineWalk};
  const std::vector<float> graphicsSpacings{base.shadingSpacing};
  const std::vector<bool> computeGrowths = twoWordList("--grow-lists", o.growLists, "off", "on", "on"),
                          graphicsGrowths{base.growLists};
  std::vector<hp::RasterMode> modes;
  for (const std::string& r : o.raster) {
    modes.push_back(hp::parseRasterMode(r));
    if (modes.back() == hp::RasterMode::Auto) throw hp::Error("bench: --raster takes compute and/or graphics");
  }
  std::vector<hp::cli::FrameCase> out;
  // --own-strands: no strand count to vary (0 here: the model's own count).
  for (std::uint32_t s : o.ownStrands ? std::vector<std::uint32_t>{0} : o.strands) {
    hp::cli::FrameCase model = base;  // the scene and asset this strand count's cases share
    model.strands = s;
    hp::cli::prepareBenchModel(model, *scene);
    for (const hp::RasterMode mode : modes) {
      hp::cli::FrameCase c = model;
      c.raster = mode;
      for (const auto& [lut, scattering] : shadingList) {
        c.lutMode = lut;
        c.scattering = scattering;
        for (const bool bounce : mode == hp::RasterMode::Compute ? computeBounces : graphicsBounces)
          for (const hp::compute::FineWalk walk : mode == hp::RasterMode::Compute ? computeWalks : graphicsWalks)
            for (const float spacing : mode == hp::RasterMode::Compute ? o.shadingSpacings : graphicsSpacings)
              for (const bool grow : mode == hp::RasterMode::Compute ? computeGrowths : graphicsGrowths) {
                c.skinBounce = bounce;
                c.fineWalk = walk;
                c.shadingSpacing = spacing;
                c.growLists = grow;
                addSampleCounts(c, o, grooms, indirects, out);  // head (and graphics hair) samples, LOD, lights, ...
              }
      }
    }
  }
  return out;
}

// Bytes per second and the fraction of the copy's only where the timestamps resolve the frame's passes.
nlohmann::json toJson(const hp::cli::FrameResult& r) {
  const bool compute = r.c.raster == hp::RasterMode::Compute;  // the shading spacing is the compute raster's
  const double copyGbs = hp::vk::copyGigabytesPerSecond(r.copyAlone);
  const double inFrameGbs = hp::vk::gigabytesPerSecond(r.copyBytes, r.passes.at("copy").medianMs);
  nlohmann::json passes = nlohmann::json::object();
  for (const auto& [name, t] : r.passes) {
    nlohmann::json p = {{"median_ms", t.medianMs}, {"min_ms", t.minMs}, {"max_ms", t.maxMs}};
    if (t.bytes > 0) p["bytes"] = t.bytes;
    if (t.bytes > 0 && r.timestampsResolvePasses) {
      const double gbs = hp::vk::gigabytesPerSecond(t.bytes, t.medianMs);
      p["gb_per_s"] = gbs;
      p["fraction_of_copy"] = gbs / copyGbs;
    }
    passes[name] = p;
  }
  const hp::Scene& scene = *r.c.scene;
  const std::string model = scene.model.kind == hp::ModelSpec::Kind::Default ? "default" : scene.model.path.string();
  return {{"model", model}, {"scene", scene.source}, {"own_strands", r.c.ownStrands},
          {"strands", r.c.strands},      {"width", r.c.width},          {"lod_fraction", r.c.lodFraction},
          {"shadowed_lights", r.c.lights},            {"bounce_samples", r.c.bounceSamples},
          {"fine_walk", hp::compute::fineWalkName(r.c.fineWalk)},
          {"fine_walk_run", hp::compute::fineWalkName(r.fineWalkRun)}, {"groom", r.c.groom ? "scene" : "none"},
          {"skin_indirect", r.c.skinIndirect},
          {"shadow_strands", r.c.shadowStrands},
          {"shading_spacing", compute ? nlohmann::json(r.c.shadingSpacing) : nlohmann::json()},
          {"grow_lists", compute ? nlohmann::json(r.c.growLists) : nlohmann::json()},
          {"shaded_vertices", compute ? nlohmann::json(r.shadedVertices) : nlohmann::json()},
          {"roughness_variation", r.c.material.roughnessVariation},
          {"height", r.c.height},        {"raster", hp::cli::frameCaseName(r.c)},
          {"lut_mode", hp::lutModeName(r.c.lutMode)},
          {"scattering", hp::render::scatteringName(r.c.scattering)},
          {"opacity_raster", hp::render::opacityRasterName(r.opacityRaster)},
          {"frame_ms", r.passes.at("frame").medianMs}, {"frame_min_ms", r.passes.at("frame").minMs},
          {"frame_max_ms", r.passes.at("frame").maxMs}, {"copy_gb_per_s", copyGbs},
          {"copy_transfer_gb_per_s", hp::vk::gigabytesPerSecond(r.copyAlone.bytes, r.copyAlone.medianMs)},
          {"copy_compute_gb_per_s", hp::vk::gigabytesPerSecond(r.copyAlone.computeBytes, r.copyAlone.computeMs)},
          {"copy_runs", r.copyAlone.runs},             {"copy_stable", r.copyAlone.stable},
          {"copy_in_frame_gb_per_s", inFrameGbs},      {"timestamps_resolve_passes", r.timestampsResolvePasses},
          {"copy_wall_ms", r.copyAlone.wallMs},        {"unresolved_because", r.unresolvedBecause},
          {"raster_entries", r.rasterEntries},         {"raster_overflow", r.rasterOverflow},
          {"host_frame_ms", r.hostMs},                 {"resident_mib", r.residentMiB},
          {"raster_target_mib", r.rasterTargetMiB},
          {"resident_growth_mib_per_frame", r.residentGrowthMiB},
          {"passes", passes}};
}

void printText(const nlohmann::json& row) {
  std::printf("%s: %u strands%s (LOD %.2f, %u shadowed lights, groom %s), %ux%u, %s: frame %.1f ms (%.1f - %.1f), host %.1f ms per "
              "frame, resident %.1f MiB (%+.2f MiB per frame)\n",
              row["model"].get<std::string>().c_str(), row["strands"].get<unsigned>(),
              row["own_strands"].get<bool>() ? " (its own)" : "", row["lod_fraction"].get<double>(), row["shadowed_lights"].get<unsigned>(),
              row["groom"].get<std::string>().c_str(), row["width"].get<unsigned>(), row["height"].get<unsigned>(), row["raster"].get<std::string>().c_str(),
              row["frame_ms"].get<double>(), row["frame_min_ms"].get<double>(), row["frame_max_ms"].get<double>(),
              row["host_frame_ms"].get<double>(), row["resident_mib"].get<double>(),
              row["resident_growth_mib_per_frame"].get<double>());
  if (const double target = row.value("raster_target_mib", 0.0); target > 0.0)
    std::printf("  raster target %.1f MiB of device memory (its lists and images%s)\n", target,
                row["grow_lists"].is_boolean() && row["grow_lists"].get<bool>() ? ", the lists grown in the frames" : "");
  std::printf("  copy yardstick %.2f GB/s alone (transfer %.2f, compute %.2f; transfer: %u submissions, %s), %.2f GB/s inside the frame%s\n",
              row["copy_gb_per_s"].get<double>(), row["copy_transfer_gb_per_s"].get<double>(),
              row["copy_compute_gb_per_s"].get<double>(), row["copy_runs"].get<unsigned>(),
              row["copy_stable"].get<bool>() ? "stable" : "not stable", row["copy_in_frame_gb_per_s"].get<double>(),
              row["timestamps_resolve_passes"].get<bool>() ? "" : "; no bandwidth derived: this device's timestamps do not resolve the passes,");
  if (!row["timestamps_resolve_passes"].get<bool>())
    std::printf("  %s\n", row["unresolved_because"].get<std::string>().c_str());
  for (const auto& [name, p] : row["passes"].items()) {
    if (name == "frame") continue;
    std::printf("  %-14s %10.2f ms  (%.2f - %.2f)", name.c_str(), p["median_ms"].get<double>(),
                p["min_ms"].get<double>(), p["max_ms"].get<double>());
    if (p.contains("gb_per_s"))
      std::printf("  %7.2f GB/s  %5.1f%% of copy", p["gb_per_s"].get<double>(),
                  100.0 * p["fraction_of_copy"].get<double>());
    std::printf("\n");
  }
  std::fflush(stdout);
}

void writeText(const std::string& path, const std::string& text) {
  hp::writeFileAtomically(path, std::as_bytes(std::span(text.data(), text.size())));
}

void run(const BenchOptions& o) {
  // Validate the options, the scene file, the model (read and built once per strand count) and the outputs
  // before touching the device.
  const auto scene = std::make_shared<const hp::Scene>(hp::cli::loadScene(o.scene));
  const auto list = cases(o, scene);
  for (const auto& [option, path] : {std::pair{"--json", o.json}, std::pair{"--plot", o.plot}})
    if (!path.empty()) hp::cli::prepareOutputFile({option, path}, hp::cli::sceneInputs(o.scene, *scene));
  auto ctx = hp::cli::createBenchContext(o.device, "bench");
  const auto& props = ctx->properties();
  nlohmann::json report = {{"device", props.deviceName},
                           {"driver_version", props.driverVersion},
                           {"api_version", std::to_string(VK_API_VERSION_MAJOR(props.apiVersion)) + "." +
                                               std::to_string(VK_API_VERSION_MINOR(props.apiVersion)) + "." +
                                               std::to_string(VK_API_VERSION_PATCH(props.apiVersion))},
                           {"frames", o.frames},
                           {"results", nlohmann::json::array()}};
  std::printf("device: %s (driver %u), median of %u frames after one warm-up\n", props.deviceName,
              props.driverVersion, o.frames);
  std::vector<hp::cli::FrameResult> results;
  for (const hp::cli::FrameCase& c : list) {
    hp::throwIfInterrupted("after " + std::to_string(results.size()) + " of " + std::to_string(list.size()) +
                           " cases" + (o.json.empty() ? "" : ": " + o.json + " not written"));
    results.push_back(hp::cli::benchFrame(*ctx, c));
    report["results"].push_back(toJson(results.back()));
    printText(report["results"].back());
  }
  if (!o.json.empty()) writeText(o.json, hp::jsonText(report) + "\n");
  if (!o.plot.empty()) writeText(o.plot, hp::cli::benchPlotSvg(results));
}

void setup(CLI::App& app) {
  auto o = std::make_shared<BenchOptions>();
  CLI::App* cmd = hp::cli::benchCommand(app);  // the suites (bench sim, bench strands, ...) are its subcommands
  CLI::Option* strands =
      cmd->add_option("--strands", o->strands, "Render strand counts, comma separated")->delimiter(',')->capture_default_str();
  hp::cli::addModelOptions(*cmd, o->scene);
  cmd->add_flag("--own-strands", o->ownStrands,
                "Draw the model's own strands (one render strand on every guide) instead of --strands")
      ->excludes(strands);
  cmd->add_option("--resolution", o->resolution, "Frame size WxH")->capture_default_str();
  cmd->add_option("--frames", o->frames, "Timed frames per case (median), after one warm-up")->capture_default_str();
  cmd->add_option("--raster", o->raster, "Raster paths: compute, graphics (comma separated)")->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--msaa", o->msaa, "Sample counts (comma separated): the head's in both paths, the hair's in the graphics path")->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--opacity-raster", o->opacityRaster, "How strands reach the opacity maps: auto, compute or graphics")
      ->capture_default_str();
  cmd->add_option("--skin-bounce", o->skinBounce,
                  "Compute raster: the skin's bounce off and/or on (comma separated)")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--skin-indirect", o->skinIndirect,
                  "The head's indirect light off and/or on (comma separated; both paths)")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--scattering", o->scattering, "single and/or dual (comma separated; physical fibre model)")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--lut-mode", o->lutModes, "Fibre models' device forms: physical, float, paper and/or direct (comma separated)")
      ->delimiter(',')
      ->capture_default_str();
  cmd->add_option("--lod-fraction", o->lodFractions,
                  "Level-of-detail fractions of the strands drawn (widened to keep coverage), comma separated")
      ->delimiter(',')->capture_default_str();
  cmd->add_option("--lights", o->lights,
                  "Shadowed directional lights per frame, 1-4 (comma separated): the sun, a rim, a fill, a top light")
      ->delimiter(',')->capture_default_str();
  cmd->add_option("--bounce-samples", o->bounceSamples,
                  "Points per strand where the skin's bounce is gathered (comma separated; the vertex count, 36, "
                  "gathers at every vertex)")
      ->delimiter(',')->capture_default_str();
  cmd->add_option("--fine-walk", o->fineWalks,
                  "Compute raster: how the fine pass walks a tile's list, auto (staged on GPUs, direct on CPU devices), "
                  "direct and/or staged (comma separated)")
      ->delimiter(',')->capture_default_str();
  cmd->add_option("--groom", o->grooms,
                  "The groom at interpolation: scene (the default head's clumps, wave and frizz) and/or none (comma "
                  "separated)")
      ->delimiter(',')->capture_default_str();
  cmd->add_option("--shading-spacing", o->shadingSpacings,
                  "Compute raster: pixels within which a strand's every other vertex takes its neighbours' mean "
                  "instead of being shaded; 0 shades every vertex (comma separated)")
      ->delimiter(',')->capture_default_str();
  cmd->add_option("--grow-lists", o->growLists,
                  "Compute raster: the tile lists start small and grow with the frames' need (on), or reserve the "
                  "close-up worst case from the start (off; comma separated)")
      ->delimiter(',')->capture_default_str();
  cmd->add_option("--shadow-strands", o->shadowStrands,
                  "Render strands drawn into the opacity maps at most, an even sample widened to keep the hair's "
                  "opacity; 0: all (comma separated)")
      ->delimiter(',')->capture_default_str();
  hp::cli::addMaterialOptions(*cmd, o->material);
  cmd->add_option("--json", o->json, "Write the report as JSON to this file");
  cmd->add_option("--plot", o->plot, "Write an SVG of ms per pass against strand count to this file");
  cmd->add_option("--device", o->device, "Vulkan device: index or name substring (env HAIRPIPE_DEVICE)");
  cmd->callback([o, cmd] {
    o->materialGiven = hp::cli::materialGiven(*cmd);
    if (cmd->get_subcommands().empty()) run(*o);  // otherwise a suite ran
  });
}
}  // namespace

HP_CLI_COMMAND(setup);
}  // namespace hp::cli::cmd_bench
