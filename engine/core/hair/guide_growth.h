#pragma once
// Contract: grows one guide per scalp vertex (paper §1). Guide g starts exactly at vertex g and leaves
// along its normal; its segment lengths follow geometricSegmentLengths(length_g, segmentRatio, P - 1)
// where length_g = length * (1 + lengthVariation * (2r - 1)) and r = hashRandom(seed, g, 0). With
// bend = 0 the guide is straight along the normal. With bend > 0 each further segment turns by that
// fraction of its remaining angle toward bendDirection (gravity, say), so the rest pose already looks
// like hair rather than a hedgehog. With colliders given, a particle that would land inside one is
// slid along its surface, keeping the segment length; with a distance field given, a particle closer
// than kGrowthClearance to its zero level is pushed out along its gradient, keeping the segment
// length. The result is deterministic.
#include <glm/glm.hpp>

#include <cstdint>
#include <functional>
#include <span>

#include "engine/core/hair/collider.h"
#include "engine/core/hair/guide_set.h"
#include "engine/core/hair/scalp_mesh.h"
#include "engine/core/hair/sdf_grid.h"

namespace hp {
struct GrowthOptions {
  std::uint32_t particlesPerGuide = kDefaultParticlesPerGuide;  // P, in [2, 64]
  float length = 0.35f;           // mean total guide length (scene units)
  float lengthVariation = 0.15f;  // relative half-range of the per-guide random length, [0, 1)
  float segmentRatio = 1.3f;      // l_(k+1) / l_k, in [1, 4]
  float bend = 0.0f;              // per-segment turn toward bendDirection, [0, 1]
  glm::vec3 bendDirection{0.0f, -1.0f, 0.0f};
  std::uint32_t seed = 1;

  void validate() const;  // throws hp::Error naming the bad field
  bool operator==(const GrowthOptions&) const = default;
};

// Where a segment starting at `position` of guide `guide` should turn (need not be unit length).
using BendField = std::function<glm::vec3(const glm::vec3& position, std::uint32_t guide)>;

// bendField, when set, replaces the constant options.bendDirection; the default head uses it to lay
// hair along the scalp and comb it back from the forehead.
// Growth keeps particles this far outside a distance field (a little more than the default pearl).
inline constexpr float kGrowthClearance = 0.0025f;

GuideSet growGuides(const ScalpMesh& scalp, const GrowthOptions& options,
                    std::span<const SphereCollider> colliders = {}, const BendField& bendField = {},
                    const DistanceFunction& field = {});

// The length guide g gets (before any collider sliding, which keeps it).
float grownGuideLength(const GrowthOptions& options, std::uint32_t guide);
}  // namespace hp
