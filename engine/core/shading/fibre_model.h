#pragma once
// Contract: the two fibre models and their exact (double) S behind one call. Physical is the
// energy-conserving model (physical.h, docs/THEORY.md §4, LutMode::Physical); Marschner is the paper's
// 2003 model (marschner.h, §3 there) that the direct, paper and float modes evaluate.
#include <glm/glm.hpp>

#include "engine/core/shading/lut.h"
#include "engine/core/shading/marschner.h"
#include "engine/core/shading/physical.h"

namespace hp {
enum class FibreModel { Physical, Marschner };

inline FibreModel fibreModelOf(LutMode mode) {
  return mode == LutMode::Physical ? FibreModel::Physical : FibreModel::Marschner;
}

inline glm::dvec3 exactS(FibreModel model, glm::dvec3 L, glm::dvec3 V, glm::dvec3 T, const HairMaterial& m) {
  return model == FibreModel::Physical ? physicalS(L, V, T, m) : marschnerS(L, V, T, m);
}
}  // namespace hp
