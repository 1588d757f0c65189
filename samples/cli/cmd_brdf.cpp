// `hairpipe brdf --in DIRS.csv --out S.csv [--mode physical|paper|float|direct] [material options] [--device D]
// [--validation]`: evaluates the fibre S ON THE DEVICE (shaders/brdf_eval.comp via
// hp::render::BrdfEvaluator) for every row of DIRS.csv.
// Input: one row per line, `lx,ly,lz,vx,vy,vz,tx,ty,tz` (L toward the light, V toward the eye, T the
// tangent); vectors need not be normalised (they are normalised on the host, in double, so any finite
// non-zero length works). A first line without any number is a header and skipped; blank lines are
// skipped. Output: one line `r,g,b` per data row, same order, no header, shortest round-trip floats,
// written atomically. Any bad input (missing or empty file, wrong column count, non-numeric, NaN/Inf,
// zero-length vector) is an hp::Error naming the file and line, and no output file is written.
#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "engine/error.h"
#include "engine/hair/atomic_write.h"
#include "engine/render/brdf_evaluator.h"
#include "engine/render/marschner_textures.h"
#include "engine/shading/lut.h"
#include "engine/vk/context.h"
#include "samples/cli/command.h"
#include "samples/cli/material_options.h"

namespace {
constexpr int kColumns = 9;
constexpr const char* kRowFormat = "lx,ly,lz,vx,vy,vz,tx,ty,tz";

struct BrdfOptions {
  std::string in;
  std::string out;
  std::string mode = "physical";
  hp::HairMaterial material;
  std::string device;
  bool validation = false;
};

std::string_view trim(std::string_view s) {
  const char* ws = " \t\r\n";
  const auto b = s.find_first_not_of(ws);
  if (b == std::string_view::npos) return {};
  return s.substr(b, s.find_last_not_of(ws) - b + 1);
}

std::vector<std::string_view> splitFields(std::string_view line) {
  std::vector<std::string_view> fields;
  for (std::size_t start = 0;;) {
    const std::size_t comma = line.find(',', start);
    fields.push_back(trim(line.substr(start, comma == std::string_view::npos ? comma : comma - start)));
    if (comma == std::string_view::npos) return fields;
    start = comma + 1;
  }
}

enum class Parse { Ok, NotANumber, OutOfRange };

Parse parseNumber(std::string_view field, double& value) {
  if (!field.empty() && field.front() == '+') field.remove_prefix(1);  // from_chars refuses a '+' sign
  const char* end = field.data() + field.size();
  auto [ptr, ec] = std::from_chars(field.data(), end, value);
  if (field.empty() || ptr != end) return Parse::NotANumber;
  if (ec == std::errc::result_out_of_range) return Parse::OutOfRange;
  return ec == std::errc() ? Parse::Ok : Parse::NotANumber;
}

// Unit vector in double, scaled first so neither tiny nor huge finite components under/overflow.
glm::dvec3 unitOrThrow(glm::dvec3 v, const char* name, const std::string& where) {
  const double scale = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
  if (scale == 0.0) throw hp::Error(where + ": " + name + " is a zero-length vector");
  v /= scale;
  return v / std::sqrt(glm::dot(v, v));
}

std::vector<hp::render::BrdfQuery> readQueries(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw hp::Error(path + ": no such input file");
  if (std::filesystem::is_directory(path, ec)) throw hp::Error(path + ": is a directory, expected a CSV file");
  std::ifstream file(path, std::ios::binary);
  if (!file) throw hp::Error(path + ": cannot open the input file (" + std::generic_category().message(errno) + ")");
  std::vector<hp::render::BrdfQuery> rows;
  std::string line;
  bool seenContent = false;
  for (std::size_t lineNo = 1; std::getline(file, line); ++lineNo) {
    if (trim(line).empty()) continue;
    const std::string where = path + ":" + std::to_string(lineNo);
    const std::vector<std::string_view> fields = splitFields(line);
    const bool first = !seenContent;
    seenContent = true;
    double v[kColumns];
    int numeric = 0;
    for (std::size_t i = 0; i < fields.size() && i < kColumns; ++i) numeric += parseNumber(fields[i], v[i]) != Parse::NotANumber;
    if (first && numeric == 0) continue;  // a header line
    if (fields.size() != kColumns)
      throw hp::Error(where + ": expected " + std::to_string(kColumns) + " comma-separated values (" + kRowFormat +
                      "), got " + std::to_string(fields.size()));
    for (int i = 0; i < kColumns; ++i) {
      const std::string column = "column " + std::to_string(i + 1) + " ('" + std::string(fields[i]) + "')";
      switch (parseNumber(fields[i], v[i])) {
        case Parse::NotANumber: throw hp::Error(where + ": " + column + " is not a number");
        case Parse::OutOfRange: throw hp::Error(where + ": " + column + " is out of range");
        case Parse::Ok: break;
      }
      if (!std::isfinite(v[i])) throw hp::Error(where + ": " + column + " is not finite");
    }
    rows.push_back({glm::vec3(unitOrThrow({v[0], v[1], v[2]}, "L", where)),
                    glm::vec3(unitOrThrow({v[3], v[4], v[5]}, "V", where)),
                    glm::vec3(unitOrThrow({v[6], v[7], v[8]}, "T", where))});
  }
  if (file.bad()) throw hp::Error(path + ": read error");
  if (rows.empty()) throw hp::Error(path + ": no data rows (expected lines " + std::string(kRowFormat) + ")");
  return rows;
}

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
  std::vector<hp::render::BrdfQuery> queries = readQueries(o.in);
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
  cmd->add_option("--in", options->in, std::string("input CSV, rows ") + kRowFormat + " (optional header line)")
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
