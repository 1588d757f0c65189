#pragma once
// Contract: guesses how an imported model maps into head space when no scene says so. Units: the
// sphere fitted to the roots is a human head (radius about 9 cm), so the scale among metres (1),
// centimetres (0.01) and millimetres (0.001) that brings its radius closest to 0.1 m wins. Up axis
// (Y or Z): roots sit on the top of the head (the mean direction from the fitted center to the
// roots points up) and hair hangs down (the mean root-to-tip direction points down); the candidate
// axis that scores higher on both wins. Each guess can be overridden; what was guessed and why is
// in the result's `reason`. Deterministic.
#include <glm/glm.hpp>

#include <filesystem>
#include <optional>
#include <span>
#include <string>

#include "engine/core/hair/model_transform.h"

namespace hp {
struct ModelGuess {
  ModelTransform transform;
  std::string units;       // "m", "cm" or "mm"
  bool unitsGuessed = false;
  bool upGuessed = false;
  float headRadius = 0.0f;  // fitted to the roots, in model units
  std::string reason;       // one line for people
};

// roots: one per strand (model units); tips: the matching last points (empty for a bare scalp).
ModelGuess guessModelTransform(std::span<const glm::vec3> roots, std::span<const glm::vec3> tips,
                               std::optional<std::string> units = {}, std::optional<UpAxis> up = {});

// The same for a model file (.hair/.tfx: roots and tips of its strands; .obj: the scalp's vertices).
ModelGuess guessModelFileTransform(const std::filesystem::path& path, std::optional<std::string> units = {},
                                   std::optional<UpAxis> up = {});

float unitScale(const std::string& units);  // "m" 1, "cm" 0.01, "mm" 0.001; throws hp::Error otherwise
}  // namespace hp
