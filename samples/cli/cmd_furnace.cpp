// `hairpipe furnace [--model physical|paper] [--theta-r DEG]... [--panels N] [material options]`:
// prints the white-furnace integral W = int S cos(theta_i) d omega_i per RGB channel (engine/core/shading/
// furnace.h), exact double-precision S, for each outgoing angle theta_r (default -80..80 deg in 20-deg
// steps). An energy-conserving fibre has W <= 1, = 1 without absorption (--absorption 0,0,0).
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "engine/core/error.h"
#include "engine/core/shading/furnace.h"
#include "samples/cli/command.h"
#include "samples/cli/material_options.h"

namespace hp::cli::cmd_furnace {  // per subcommand: file-local names stay apart in a unity build

namespace {
struct FurnaceOptions {
  std::string model = "physical";
  std::vector<double> thetaR;
  int panels = 64;
  hp::HairMaterial material;
};

void runFurnace(const FurnaceOptions& o) {
  if (o.model != "physical" && o.model != "paper")
    throw hp::Error("--model " + o.model + ": expected physical or paper");
  if (o.panels < 4 || o.panels > 4096) throw hp::Error("--panels must be in [4, 4096]");
  o.material.validate();
  std::vector<double> angles = o.thetaR;
  if (angles.empty())
    for (int d = -80; d <= 80; d += 20) angles.push_back(d);
  const hp::FibreModel model = o.model == "physical" ? hp::FibreModel::Physical : hp::FibreModel::Marschner;
  std::cout << "white furnace, " << o.model << " model: W = int S cos(theta_i) d omega_i per channel\n"
            << "theta_r_deg,r,g,b\n"
            << std::setprecision(6);
  for (double deg : angles) {
    if (!(deg >= -90.0 && deg <= 90.0)) throw hp::Error("--theta-r " + std::to_string(deg) + ": must be in [-90, 90]");
    glm::dvec3 w = hp::whiteFurnace(model, std::sin(glm::radians(deg)), o.material, o.panels);
    std::cout << deg << "," << w.r << "," << w.g << "," << w.b << "\n";
  }
}

void setupFurnace(CLI::App& app) {
  auto options = std::make_shared<FurnaceOptions>();
  CLI::App* cmd = app.add_subcommand("furnace", "print the white-furnace integral of a fibre model per channel");
  cmd->add_option("--model", options->model, "physical (default) or paper (the 2003 Marschner model)");
  cmd->add_option("--theta-r", options->thetaR, "outgoing longitudinal angle(s) in degrees (repeatable)");
  cmd->add_option("--panels", options->panels, "quadrature panels per axis, 8 nodes each (default 64)");
  hp::cli::addMaterialOptions(*cmd, options->material);
  cmd->callback([options] { runFurnace(*options); });
}
}  // namespace

HP_CLI_COMMAND(setupFurnace);
}  // namespace hp::cli::cmd_furnace
