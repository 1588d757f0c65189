#pragma once
// Test support: a patch of hair with a parting, for the tests of parted scalp triangles (engine, CLI). Roots on
// a 9 x 9 patch of a head sphere's crown (radius kPartedCrownRadius at the origin, y up), 1 cm apart; each
// guide lies along the head 2 mm out, turning from its root toward +x (x >= partX) or -x (x < partX) over 80
// degrees of arc: a parting along z at partX.
#include <glm/glm.hpp>

#include <cmath>

#include "engine/core/hair/guide_set.h"
#include "engine/core/hair/hair_file.h"

namespace hp::test {
inline constexpr float kPartedCrownRadius = 0.1f;

inline GuideSet partedCrown(float partX) {
  constexpr float R = kPartedCrownRadius;
  GuideSet g;
  g.particlesPerGuide = 7;
  for (int i = 0; i < 9; ++i)
    for (int j = 0; j < 9; ++j) {
      const glm::vec3 r = glm::normalize(glm::vec3(0.01f * float(i - 4) + 0.005f, R, 0.01f * float(j - 4)));
      const glm::vec3 side(r.x >= partX / R ? 1.0f : -1.0f, 0.0f, 0.0f);
      const glm::vec3 s = glm::normalize(side - glm::dot(side, r) * r);
      for (int k = 0; k < 7; ++k) {
        const float a = glm::radians(80.0f) * float(k) / 6.0f;
        g.positions.push_back((R + 0.002f * float(k > 0)) * (std::cos(a) * r + std::sin(a) * s));
      }
    }
  return g;
}

// The guides as a .hair model's strands.
inline HairFileData hairFileOf(const GuideSet& g) {
  HairFileData data;
  data.strandCount = g.guideCount();
  data.defaultSegments = g.particlesPerGuide - 1;
  data.points = g.positions;
  return data;
}
}  // namespace hp::test
