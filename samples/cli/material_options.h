#pragma once
// Contract: the one set of hair-material options every `hairpipe` command uses:
//   --eta N, --absorption R,G,B | --color R,G,B (converted by hp::absorptionFromColor: the colour of
//   one straight pass through the fibre centre), --alpha-r DEG, --beta-r DEG, --kg N, --wc DEG,
//   --deta N, --dhm N, --beta-n DEG (physical model).
// Values are written into `material` (angles converted to radians) as they are parsed; an invalid
// value throws hp::Error naming the option (e.g. "--eta 0.9: HairMaterial.eta = 0.9 is invalid ...").
#include <CLI/CLI.hpp>

#include "engine/core/shading/material.h"

namespace hp::cli {
void addMaterialOptions(CLI::App& app, HairMaterial& material);
// Whether any material option was given (then the options' material replaces the scene's).
bool materialGiven(const CLI::App& app);
}  // namespace hp::cli
