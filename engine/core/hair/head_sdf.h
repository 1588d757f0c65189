#pragma once
// Contract: the default head as one signed distance field, in metres, Y up, face toward +Z, origin
// at the center of the cranium. Cranium, brow, eye sockets with eyes, nose, cheekbones, jaw, chin,
// lips, ears, neck, shoulders and upper chest are primitives (sdf_program.h) blended with a
// smooth minimum; the chest is cut flat at kHeadFieldLow.y so the surface is closed. The scalp, the
// hairline and the face region are read from the same field. Pure and deterministic.
#include <glm/glm.hpp>

#include <span>

#include "engine/core/hair/sdf_program.h"

namespace hp {
// The field as a program (its leaves in the order above); headDistance(p) == headField()(p).
const sdf::Program& headField();
float headDistance(const glm::vec3& p);
glm::vec3 headGradient(const glm::vec3& p);  // central differences of headDistance (not normalized)

// A box that holds the whole surface with a margin.
inline constexpr glm::vec3 kHeadFieldLow{-0.27f, -0.40f, -0.16f};
inline constexpr glm::vec3 kHeadFieldHigh{0.27f, 0.115f, 0.16f};
// The cranium's center: rays from here meet the scalp.
inline constexpr glm::vec3 kCraniumCenter{0.0f, 0.005f, -0.012f};

// For each unit direction, the surface point on the ray from kCraniumCenter along it: a point with
// |field| < 0.1 um (on either side) where the ray leaves the field within 0.3 m (every direction to the
// scalp does), else the outer end of the last bracket (0.3 m out for a ray still inside there, e.g. into
// the chest); and headGradient there. Evaluated in batches over the rays. surfaces holds one point per
// ray; gradients is empty (not computed) or one per ray (else hp::Error).
void headSurfacesAlong(std::span<const glm::vec3> dirs, std::span<glm::vec3> surfaces, std::span<glm::vec3> gradients);

// Hair grows where the direction from the cranium center is above the hairline: high at the
// forehead, above the ears at the sides, low at the nape.
bool aboveHairline(const glm::vec3& dir);

// The face, for coverage checks: surface points in front of the ears, between the brow and the chin.
bool inFaceRegion(const glm::vec3& surfacePoint);
}  // namespace hp
