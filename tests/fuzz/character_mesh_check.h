#pragma once
// Shared by the character mesh fuzz targets: the properties every accepted CharacterMesh has (indices in
// range, unit normals, weights finite and summing to 1 over joints of the skeleton, parents before their
// children, clips' keys in order), and that binding its own vertices as roots and skinning it in its rest
// pose give finite results.
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "engine/core/error.h"
#include "engine/core/hair/character_mesh.h"
#include "engine/core/hair/root_binding.h"
#include "engine/core/hair/skeleton_pose.h"
#include "tests/fuzz/fuzz_check.h"

namespace hp::fuzz {
inline void checkCharacterMesh(const CharacterMesh& m) {
  HP_FUZZ_REQUIRE(!m.triangles.empty() && m.normals.size() == m.positions.size());
  for (const auto& t : m.triangles) HP_FUZZ_REQUIRE(t.x < m.positions.size() && t.y < m.positions.size() && t.z < m.positions.size());
  for (std::size_t v = 0; v < m.positions.size(); ++v) {
    HP_FUZZ_REQUIRE(finite(m.positions[v]) && std::abs(glm::length(m.normals[v]) - 1.0f) < 1e-3f);
    if (!m.skinned()) continue;
    float sum = 0.0f;
    for (int k = 0; k < 4; ++k) {
      HP_FUZZ_REQUIRE(std::isfinite(m.weights[v][k]) && m.weights[v][k] >= 0.0f && m.joints[v][k] < m.skeleton.size());
      sum += m.weights[v][k];
    }
    HP_FUZZ_REQUIRE(std::abs(sum - 1.0f) < 1e-3f);
  }
  for (std::size_t j = 0; j < m.skeleton.size(); ++j) HP_FUZZ_REQUIRE(m.skeleton[j].parent < std::int32_t(j));
  for (const auto& clip : m.animations)
    for (const auto& ch : clip.channels) {
      HP_FUZZ_REQUIRE(ch.joint < m.skeleton.size() && !ch.times.empty() && ch.times.size() == ch.values.size());
      for (std::size_t k = 1; k < ch.times.size(); ++k) HP_FUZZ_REQUIRE(ch.times[k] >= ch.times[k - 1]);
    }
  // The first triangles' corners, bound as roots, lie on the mesh (relative to the mesh's size).
  const std::size_t n = std::min<std::size_t>(m.triangles.size(), 16);
  std::vector<glm::vec3> roots;
  for (std::size_t t = 0; t < n; ++t) roots.push_back(m.positions[m.triangles[t].x]);
  glm::vec3 lo(INFINITY), hi(-INFINITY);
  for (const auto& p : m.positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
  const float size = glm::length(hi - lo);
  if (!std::isfinite(size) || size > 1e15f) return;  // float rounding alone exceeds any bound there
  const RootBindings b = bindRoots(roots, m.positions, m.triangles, 0.01f);
  for (std::size_t r = 0; r < n; ++r) {
    HP_FUZZ_REQUIRE(b.roots[r].triangle < m.triangles.size() && std::isfinite(b.roots[r].distance));
    HP_FUZZ_REQUIRE(b.roots[r].distance <= 1e-4f * size + 1e-30f);
  }
  if (!m.skinned()) return;
  try {
    for (const auto& p : skinMesh(m, skinningMatrices(m, restPose(m))).positions) (void)p;
  } catch (const Error&) {
    HP_FUZZ_REQUIRE(false && "skinning an accepted mesh threw");
  }
}
}  // namespace hp::fuzz
