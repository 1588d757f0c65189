// `hairpipe lut --out DIR [--mode paper|float|physical] [material options]`: builds the Marschner lookup
// textures on the CPU and writes, per texture NAME: NAME_rgb.pfm and NAME_a.pfm (stored float values,
// channels 0-2 and 3), NAME.png and NAME_a.png (8-bit previews), plus lut.json (layout,
// parameterisation, per-channel scale factors, material, files). Every file is written atomically.

#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/core/error.h"
#include "engine/core/hair/atomic_write.h"
#include "samples/tools/png_file.h"
#include "engine/core/shading/lut.h"
#include "samples/tools/host/lut_export.h"
#include "samples/cli/command.h"
#include "samples/cli/material_options.h"
#include "samples/cli/output_paths.h"
#include "samples/tools/host/json_text.h"

namespace hp::cli::cmd_lut {  // per subcommand: file-local names stay apart in a unity build

namespace {
struct LutOptions {
  std::string out;
  std::string mode = "float";
  hp::HairMaterial material;
};

std::vector<std::byte> bytesOf(const std::string& s) {
  std::vector<std::byte> b(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) b[i] = std::byte(s[i]);
  return b;
}

void writeTexture(const std::filesystem::path& dir, const hp::LutTexture& t, nlohmann::json& files) {
  for (hp::LutChannels which : {hp::LutChannels::Rgb, hp::LutChannels::Alpha}) {
    std::string suffix = which == hp::LutChannels::Rgb ? "_rgb" : "_a";
    std::string pfm = t.name + suffix + ".pfm";
    std::string png = t.name + (which == hp::LutChannels::Rgb ? "" : "_a") + ".png";
    hp::writeFileAtomically(dir / pfm, hp::lutTexturePfm(t, which));
    const hp::PreviewImage preview = hp::lutPreviewRgb8(t, which);
    hp::writePng(dir / png, preview.width, preview.height, 3, preview.rgb);
    files[t.name].push_back(pfm);
    files[t.name].push_back(png);
  }
}

void run(const LutOptions& o) {
  const hp::LutMode mode = hp::parseLutMode(o.mode);
  const std::filesystem::path dir(o.out);
  hp::cli::prepareOutputFolder({"--out", dir}, {});
  hp::MarschnerLut lut = hp::buildLut(mode, o.material);
  nlohmann::json desc = hp::describeLut(lut);
  nlohmann::json files = nlohmann::json::object();
  for (const hp::LutTexture& t : lut.textures) writeTexture(dir, t, files);
  desc["files"] = files;
  desc["pfm_values"] = "stored texel values; physical value = stored * scale (per channel)";
  hp::writeFileAtomically(dir / "lut.json", bytesOf(hp::jsonText(desc) + "\n"));
  std::cout << "wrote " << lut.textures.size() << " " << o.mode << " textures to " << dir.string() << "\n";
}

void setupLut(CLI::App& app) {
  auto options = std::make_shared<LutOptions>();
  CLI::App* cmd = app.add_subcommand("lut", "build the Marschner lookup textures (PFM + PNG + JSON)");
  cmd->add_option("--out", options->out, "output directory (created if missing)")->required();
  cmd->add_option("--mode", options->mode, "paper (RGBA8 128x128, the paper's form), float (RGBA16F) or physical (the energy-conserving model)")
      ->check(CLI::IsMember({"paper", "float", "physical"}));
  hp::cli::addMaterialOptions(*cmd, options->material);
  cmd->callback([options] { run(*options); });
}
}  // namespace

HP_CLI_COMMAND(setupLut);
}  // namespace hp::cli::cmd_lut
