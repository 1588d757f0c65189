#pragma once
// Contract: the project's LUT accuracy metric (docs/SHADING.md "Accuracy"), over uniformly random (L, V, T) with a fixed seed:
// per sample and channel e = |S_mode - S_exact| / (|S_exact| + 0.01); reports median(e), p99(e) and
// sum|S_mode - S_exact| / sum|S_exact|. S_exact is the exact S of `model`.
#include <functional>
#include <string>

#include <glm/glm.hpp>

#include "engine/core/shading/fibre_model.h"

namespace hp::test {
struct AccuracyStats {
  double median = 0, p99 = 0, max = 0, relativeSum = 0;
  std::string str() const;
};
using SEvaluator = std::function<glm::dvec3(glm::dvec3 L, glm::dvec3 V, glm::dvec3 T)>;
AccuracyStats measureAccuracy(const SEvaluator& mode, const HairMaterial& m, int samples, unsigned seed,
                              FibreModel model = FibreModel::Marschner);
}  // namespace hp::test
