#include "engine/core/hair/guide_set.h"

#include <string>

#include "engine/core/error.h"

namespace hp {
std::vector<glm::vec3> GuideSet::roots() const {
  std::vector<glm::vec3> out(guideCount());
  for (std::uint32_t g = 0; g < out.size(); ++g) out[g] = root(g);
  return out;
}

void checkParticlesPerGuide(std::uint32_t particles, const char* what) {
  if (particles < kMinParticlesPerGuide || particles > kMaxParticlesPerGuide)
    throw Error(std::string(what) + ": particles per guide must be in [" +
                std::to_string(kMinParticlesPerGuide) + ", " + std::to_string(kMaxParticlesPerGuide) +
                "], got " + std::to_string(particles));
}
}  // namespace hp
