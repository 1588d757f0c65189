#pragma once
// Contract: the groom options shared by `render`, `reference`, `view` (through frame options) and `strands`:
// --no-groom (start from no groom at all), then --clump, --curl, --frizz, each overriding its part of the
// scene's "groom" section (engine/core/hair/groom.h). applyGroomOptions validates the result (hp::Error naming the option).
#include <CLI/CLI.hpp>

#include <vector>

#include "engine/core/hair/groom.h"

namespace hp::cli {
struct GroomOptions {
  bool none = false;         // --no-groom
  std::vector<float> clump;  // COUNT,STRENGTH[,SHAPE]
  std::vector<float> curl;   // RADIUS,TURNS[,VARIATION]
  std::vector<float> frizz;  // AMPLITUDE[,FREQUENCY[,HAIRLINE[,WIDTH]]]
};

void addGroomOptions(CLI::App& cmd, GroomOptions& o);
void applyGroomOptions(const GroomOptions& o, GroomSettings& groom);
}  // namespace hp::cli
