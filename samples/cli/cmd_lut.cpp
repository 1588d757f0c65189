// `hairpipe lut --out DIR [--mode paper|float] [material options]`: builds the Marschner lookup
// textures on the CPU and writes, per texture NAME: NAME_rgb.pfm and NAME_a.pfm (stored float values,
// channels 0-2 and 3), NAME.png and NAME_a.png (8-bit previews), plus lut.json (layout,
// parameterisation, per-channel scale factors, material, files). Every file is written atomically.
#include <png.h>

#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "engine/error.h"
#include "engine/hair/atomic_write.h"
#include "engine/shading/lut.h"
#include "engine/shading/lut_export.h"
#include "samples/cli/command.h"
#include "samples/cli/material_options.h"

namespace {
struct LutOptions {
  std::string out;
  std::string mode = "float";
  hp::HairMaterial material;
};

void appendPng(png_structp png, png_bytep data, png_size_t size) {
  auto* out = static_cast<std::vector<std::byte>*>(png_get_io_ptr(png));
  for (png_size_t i = 0; i < size; ++i) out->push_back(std::byte(data[i]));
}

std::vector<std::byte> encodePng(const hp::PreviewImage& img) {
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png ? png_create_info_struct(png) : nullptr;
  if (!info) throw hp::Error("libpng: cannot create the PNG writer");
  std::vector<std::byte> out;
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    throw hp::Error("libpng: encoding the LUT preview failed");
  }
  png_set_write_fn(png, &out, appendPng, nullptr);
  png_set_IHDR(png, info, img.width, img.height, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  for (std::uint32_t y = 0; y < img.height; ++y)
    png_write_row(png, const_cast<png_bytep>(&img.rgb[std::size_t(y) * img.width * 3]));
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  return out;
}

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
    hp::writeFileAtomically(dir / png, encodePng(hp::lutPreviewRgb8(t, which)));
    files[t.name].push_back(pfm);
    files[t.name].push_back(png);
  }
}

void run(const LutOptions& o) {
  hp::MarschnerLut lut = hp::buildLut(hp::parseLutMode(o.mode), o.material);
  std::filesystem::path dir(o.out);
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw hp::Error("cannot create directory " + dir.string() + ": " + ec.message());
  nlohmann::json desc = hp::describeLut(lut);
  nlohmann::json files = nlohmann::json::object();
  for (const hp::LutTexture& t : lut.textures) writeTexture(dir, t, files);
  desc["files"] = files;
  desc["pfm_values"] = "stored texel values; physical value = stored * scale (per channel)";
  hp::writeFileAtomically(dir / "lut.json", bytesOf(desc.dump(2) + "\n"));
  std::cout << "wrote " << lut.textures.size() << " " << o.mode << " textures to " << dir.string() << "\n";
}

void setupLut(CLI::App& app) {
  auto options = std::make_shared<LutOptions>();
  CLI::App* cmd = app.add_subcommand("lut", "build the Marschner lookup textures (PFM + PNG + JSON)");
  cmd->add_option("--out", options->out, "output directory (created if missing)")->required();
  cmd->add_option("--mode", options->mode, "paper (RGBA8 128x128, the paper's form) or float (RGBA16F)")
      ->check(CLI::IsMember({"paper", "float"}));
  hp::cli::addMaterialOptions(*cmd, options->material);
  cmd->callback([options] { run(*options); });
}
}  // namespace

HP_CLI_COMMAND(setupLut);
