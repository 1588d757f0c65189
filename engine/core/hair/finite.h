#pragma once
// Contract: whether every component of a matrix is finite (the check every API taking transforms makes).
#include <glm/glm.hpp>

#include <cmath>

namespace hp {
inline bool allFinite(const glm::mat4& m) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(m[c][r])) return false;
  return true;
}
}  // namespace hp
