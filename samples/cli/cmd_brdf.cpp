// `hairpipe brdf --in DIRS.csv --out S.csv [--mode physical|paper|float|direct] [material options] [--device D]
// [--validation]`: evaluates the fibre S ON THE DEVICE (shaders/brdf_eval.comp via
// hp::render::BrdfEvaluator) for every row of DIRS.csv.
// Input: one row per line, `lx,ly,lz,vx,vy,vz,tx,ty,tz` (L toward the light, V toward the eye, T the
// tangent); vectors need not be normalised (they are normalised on the host, in double, so any finite
// non-zero length works). A first line without any number is a header and skipped; blank lines are
// skipped. Output: one line `r,g,b` per data row, same order, no header, shortest round-trip floats,
// written atomically. Any bad input (missing or empty file, wrong column count, non-numeric, NaN/Inf,
// zero-length vector) is an hp::Error naming the file and line, and no output file is written.
#include <charconv>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "engine/core/error.h"
#include "engine/core/hair/atomic_write.h"
#include "samples/tools/brdf_evaluator.h"
#include "compute/raster/marschner_textures.h"
#include "engine/core/shading/lut.h"
#include "engine/vk/context.h"
#include "samples/cli/brdf_queries.h"
#include "samples/cli/command.h"
#include "samples/cli/material_options.h"
#include "samples/cli/output_paths.h"

namespace hp::cli::cmd_brdf {  // per subcommand: file-local names stay apart in a unity build

namespace {
struct BrdfOptions {
  std::string in;
  std::string out;
  std::string mode = "physical";
  hp::HairMaterial material;
  std::string device;
  bool validation = false;
};

std::vector<std::byte> formatRows(const std::vector<glm::vec3>& s, const std::string& in) {
  std::string text;
  text.reserve(s.size() * 40);
  char buf[32];
  for (std::size_t row = 0; row < s.size(); ++row)
    for (int c = 0; c < 3; ++c) {
      if (!std::isfinite(s[row][c]))
        throw hp::Error("the device returned a non-finite S for " + in + " data row " + std::to_string(row + 1));
      auto [end, ec] = std::to_chars(buf, buf + sizeof(buf), s[row][c]);  // shortest round-trip form
      text.append(buf, end);
      text.push_back(c == 2 ? '\n' : ',');
    }
  const auto* bytes = reinterpret_cast<const std::byte*>(text.data());
  return {bytes, bytes + text.size()};
}

void runBrdf(const BrdfOptions& o) {
  if (o.mode != "physical" && o.mode != "paper" && o.mode != "float" && o.mode != "direct")
    throw hp::Error("--mode " + o.mode + ": expected physical, paper, float or direct");
  const hp::LutMode mode = hp::parseLutMode(o.mode);
  o.material.validate();
  hp::cli::prepareOutputFile({"--out", o.out}, {{"--in", o.in}});
  std::vector<hp::render::BrdfQuery> queries = hp::cli::readBrdfQueries(o.in);
  hp::vk::ContextOptions ctxOptions;
  ctxOptions.device = o.device;
  ctxOptions.validation = o.validation;
  auto ctx = hp::vk::Context::createHeadless(ctxOptions);
  ctx->validationLog().setEcho(true);
  std::vector<glm::vec3> s;
  {
    hp::render::MarschnerTextures textures(*ctx, o.material, mode);
    s = hp::render::evaluateBrdfOnDevice(*ctx, textures, queries);
  }
  if (ctx->validationEnabled() && ctx->validationLog().problemCount() > 0)
    throw hp::Error(std::to_string(ctx->validationLog().problemCount()) + " Vulkan validation message(s) were reported");
  hp::writeFileAtomically(o.out, formatRows(s, o.in));
  std::cout << "wrote S for " << s.size() << " rows (" << o.mode << ", " << ctx->properties().deviceName << ") to "
            << o.out << "\n";
}

void setupBrdf(CLI::App& app) {
  auto options = std::make_shared<BrdfOptions>();
  CLI::App* cmd = app.add_subcommand("brdf", "evaluate the fibre S on the device for rows of (L, V, T)");
  cmd->add_option("--in", options->in, std::string("input CSV, rows ") + hp::cli::kBrdfRowFormat + " (optional header line)")
      ->required();
  cmd->add_option("--out", options->out, "output CSV, rows r,g,b in input order (written atomically)")->required();
  // Checked in runBrdf (hp::Error, exit code 1) rather than by CLI11, like the material options.
  cmd->add_option("--mode", options->mode, "physical (energy-conserving model, RGBA16F LUTs, default); the paper's model: float (RGBA16F LUTs), "
                  "paper (RGBA8 128x128) or direct (analytic)");
  hp::cli::addMaterialOptions(*cmd, options->material);
  cmd->add_option("--device", options->device, "device name substring or index (default: HAIRPIPE_DEVICE, else best)");
  cmd->add_flag("--validation", options->validation, "enable the Vulkan validation layer");
  cmd->callback([options] { runBrdf(*options); });
}
}  // namespace

HP_CLI_COMMAND(setupBrdf);
}  // namespace hp::cli::cmd_brdf
