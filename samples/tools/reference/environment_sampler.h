#pragma once
// Contract: importance sampling of an environment map for the path tracer's next-event estimation: a texel
// is picked with probability proportional to its solid angle times the largest luminance among it and its
// eight neighbours (the bilinear lookup's reach, so every direction with radiance has density), then a
// direction uniform in solid angle within it. pdf() is the exact solid-angle density of sample(). Empty
// (nothing to sample) when the map is black. docs/SHADING.md "Reference".
#include <vector>

#include <glm/glm.hpp>

#include "engine/core/shading/environment_map.h"
#include "samples/tools/reference/sampling.h"

namespace hp::reference {
class EnvironmentSampler {
 public:
  explicit EnvironmentSampler(const EnvironmentMap& map);
  bool empty() const { return total_ <= 0.0; }
  glm::dvec3 sample(Sampler& rng, double& pdf) const;  // unit direction toward the environment
  double pdf(const glm::dvec3& dir) const;

 private:
  std::size_t texelOf(const glm::dvec3& dir) const;
  double texelPdf(std::size_t texel) const;  // solid-angle density inside the texel

  const EnvironmentMap& map_;
  std::vector<double> cdf_;  // running sums of the texels' weights, width x height
  double total_ = 0.0;
};
}  // namespace hp::reference
