#pragma once
// Contract: hair roots bound to a mesh (docs/THEORY.md §8.6). Each root binds to its nearest triangle: the
// barycentric coordinates of its projection on the triangle's plane and its signed offset along the
// triangle's unit normal, so boundRootPosition gives the root back exactly (to float rounding) on the mesh
// it was bound to, and on a deformed mesh moves with its triangle: rigidly with a rigidly moved triangle.
// The search is exact (a uniform grid of triangle boxes searched in growing shells until no nearer triangle
// can remain). Roots farther than `farDistance` from every triangle are counted, not refused: the caller
// reports them. boundRootSkin blends the triangle's vertex weights by the (clamped) barycentrics into four
// per root, as a TressFX exporter gives each strand the weights of the mesh where it grows.
#include <glm/glm.hpp>

#include <cstdint>
#include <span>
#include <vector>

#include "engine/core/hair/character_mesh.h"
#include "shaders/shared/simulate.h"

namespace hp {
struct RootBinding {
  std::uint32_t triangle = 0;
  glm::vec2 barycentric{0.0f};  // weights of the triangle's 2nd and 3rd vertex; the 1st has 1 - x - y
  float offset = 0.0f;          // along the triangle's unit normal (outside: positive)
  float distance = 0.0f;        // from the root to the triangle when bound
};

struct RootBindings {
  std::vector<RootBinding> roots;
  std::uint32_t farRoots = 0;   // roots farther than farDistance from the mesh
  float farDistance = 0.0f;
  float meanDistance = 0.0f;
  float maxDistance = 0.0f;
};

RootBindings bindRoots(std::span<const glm::vec3> roots, std::span<const glm::vec3> positions,
                       std::span<const glm::uvec3> triangles, float farDistance);
glm::vec3 boundRootPosition(const RootBinding& binding, std::span<const glm::vec3> positions,
                            std::span<const glm::uvec3> triangles);
// Per root, for a skinned mesh: four joints and weights summing to 1.
std::vector<gpu::SkinWeights> boundRootSkin(const RootBindings& bindings, const CharacterMesh& mesh);
}  // namespace hp
