#pragma once
// Contract: the groom detail the interpolation adds to each render strand (shaders/interpolate.glsl,
// docs/THEORY.md "Groom detail"): clumping toward clump centres in each scalp triangle, curl around the
// clumped centreline and frizz, all deterministic per strand. A default-constructed GroomSettings adds
// nothing (every strand the plain blend of its three guides); recommendedGroom() is what scenes and the
// public API start from. Host-only; validate() throws hp::Error naming the field.
#include <cstdint>

#include "shaders/shared/strands.h"

namespace hp {
struct GroomSettings {
  std::uint32_t clumpsPerTriangle = 0;  // clump centres hashed in each scalp triangle, [0, 64]; 0: none
  float clumpStrength = 0.0f;           // pull toward the centre at the tip, [0, 1]
  float clumpShape = 1.0f;              // the pull along the strand is strength x v^shape, [0.1, 10]
  float curlRadius = 0.0f;              // helix radius around the centreline (scene units), [0, 1]
  float curlTurns = 0.0f;               // turns per scene unit of strand length, [0, 10000]
  float curlVariation = 0.0f;           // per-strand spread of radius and turns (+-half of it), [0, 1]
  float frizzAmplitude = 0.0f;          // noise across the strand at the tip (scene units; v^2), [0, 1]
  float frizzFrequency = 40.0f;         // noise cycles per scene unit of length, (0, 10000]
  // Frizz by region: the amplitude times 1 + frizzHairline x exp(-d / frizzHairlineWidth), d the strand's
  // scalp triangle's distance from the hairline (engine/core/hair/hairline_distance.h). [0, 100]; 0: even.
  float frizzHairline = 0.0f;
  float frizzHairlineWidth = 0.02f;     // scene units, (0, 10]
  bool operator==(const GroomSettings&) const = default;
  bool any() const { return clumpsPerTriangle > 0 || curlRadius > 0.0f || frizzAmplitude > 0.0f; }
  void validate() const;
};

// The groom a scene and the public API's GroomSettings start from, chosen by looking at the default head
// (docs/THEORY.md "Groom detail"): four clumps a scalp triangle pulling the tips 40% of the way in (v^1.5), a
// gentle wave (4 mm radius, 5 turns a metre, +-25% per strand), 0.8 mm of frizz at the tips and up to five
// times that at the hairline. Lengths in scene units, metres for the default head.
constexpr GroomSettings recommendedGroom() {
  GroomSettings g;
  g.clumpsPerTriangle = 4;
  g.clumpStrength = 0.4f;
  g.clumpShape = 1.5f;
  g.curlRadius = 0.004f;
  g.curlTurns = 5.0f;
  g.curlVariation = 0.5f;
  g.frizzAmplitude = 0.0008f;
  g.frizzHairline = 4.0f;
  return g;
}

gpu::GroomParams groomParams(const GroomSettings& groom);
}  // namespace hp
