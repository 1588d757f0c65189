#include "samples/tools/host/synthetic_hair.h"

#include <algorithm>
#include <cmath>

#include "engine/core/error.h"
#include "engine/core/hair/rng.h"

namespace hp {
namespace {
// Per-strand point counts around the mean, adjusted in pairs so the total stays exact.
std::vector<std::uint16_t> segmentCounts(const SyntheticHairOptions& o) {
  std::vector<std::uint32_t> n(o.strands, o.points / o.strands);
  for (std::uint32_t i = 0; i < o.points % o.strands; ++i) ++n[i];
  for (std::uint32_t i = 0; i + 1 < o.strands; i += 2) {
    auto d = static_cast<std::uint32_t>(hashRandom(o.seed, i, 9) * 0.3f * float(n[i]));
    d = std::min({d, n[i + 1] - 2, 65536u - n[i]});
    n[i] += d, n[i + 1] -= d;
  }
  std::vector<std::uint16_t> segments(o.strands);
  for (std::uint32_t i = 0; i < o.strands; ++i) segments[i] = static_cast<std::uint16_t>(n[i] - 1);
  return segments;
}

glm::vec3 rootDirection(std::uint32_t seed, std::uint32_t i) {
  float y = 0.1f + 0.9f * hashRandom(seed, i, 1);  // upper cap
  float phi = 6.2831853f * hashRandom(seed, i, 2);
  float r = std::sqrt(1.0f - y * y);
  return {r * std::cos(phi), y, r * std::sin(phi)};
}
}  // namespace

HairFileData makeSyntheticHair(const SyntheticHairOptions& o) {
  if (o.strands == 0 || o.points < 2ull * o.strands || o.points > 65536ull * o.strands)
    throw Error("synthetic hair: points must be in [2, 65536] per strand");
  HairFileData d;
  d.strandCount = o.strands;
  d.segments = segmentCounts(o);
  d.setInfoText("hairpipe synthetic hair");
  d.points.reserve(o.points);
  for (std::uint32_t s = 0; s < o.strands; ++s) {
    glm::vec3 u = rootDirection(o.seed, s);
    glm::vec3 root = o.center + u * o.radius;
    glm::vec3 side = glm::normalize(glm::cross(u, glm::vec3(0, 1, 0.01f)));
    float phase = 6.2831853f * hashRandom(o.seed, s, 3);
    std::uint32_t n = d.segments[s] + 1u;
    for (std::uint32_t k = 0; k < n; ++k) {
      float t = float(k) / float(n - 1);
      glm::vec3 hang = u * (0.25f * o.length * t) + glm::vec3(0, -1, 0) * (o.length * t * t);
      glm::vec3 wave = side * (0.02f * o.length * std::sin(phase + 25.0f * t) * t);
      d.points.push_back(root + hang + wave);
    }
  }
  return d;
}
}  // namespace hp
