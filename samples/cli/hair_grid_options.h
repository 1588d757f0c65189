#pragma once
// Contract: the hair grid's options shared by `simulate` and the frame commands (`render`, `reference`, `view`):
// --volume, --volume-target, --friction, --grid-resolution, each overriding its field of the scene's
// "simulation" section (engine/core/hair/sim_params.h, docs/THEORY.md §2.7). applyHairGridOptions validates the
// result (hp::Error naming the parameter).
#include <CLI/CLI.hpp>

#include <optional>

#include "engine/core/hair/sim_params.h"

namespace hp::cli {
struct HairGridOptions {
  std::optional<double> volume, volumeTarget, friction;
  std::optional<std::uint32_t> resolution;
};

void addHairGridOptions(CLI::App& cmd, HairGridOptions& o);
void applyHairGridOptions(const HairGridOptions& o, SimulationParams& params);
}  // namespace hp::cli
