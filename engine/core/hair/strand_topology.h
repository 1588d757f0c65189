#pragma once
// Contract: the interpolation topology of paper §1. Each triangle names three guides (A, B, C); each
// render strand sits in one triangle at barycentrics X = (X1, X2, X3), X1 + X2 + X3 = 1, all >= 0,
// and every frame becomes K_j = X1 A_j + X2 B_j + X3 C_j. Barycentrics come from the fold method
// (docs/THEORY.md §1.4), which is uniform over the triangle. The strands are in level-of-detail order:
// any prefix of them (the first fraction f of all strands) holds about f of each triangle's strands
// (within one), so drawing a prefix thins the hair evenly. Everything derives from hashRandom with the
// density seed: the same inputs give the same topology on every run and machine.
#include <glm/glm.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace hp {
struct StrandBinding {
  std::uint32_t triangle = 0;  // index into InterpolationTopology::triangles
  glm::vec3 barycentric{1.0f / 3.0f};  // weights of the triangle's guides A, B, C
  float random = 0.0f;         // per-strand value in [0, 1) for variation (length, colour, ...)
};

struct InterpolationTopology {
  std::vector<glm::uvec3> triangles;     // guide indices
  std::vector<StrandBinding> strands;    // render strands
  // Per triangle, its distance from the hairline (hairline_distance.h), in the roots' units; filled by
  // buildInterpolationTopology. Empty (a topology built by hand): every triangle far from any hairline.
  std::vector<float> hairlineDistance;
};

struct DensityOptions {
  // Guides: one render strand on every guide (a model's own strands, its own shape); Auto: Guides when there
  // are at least totalStrands guides (a model with many strands draws its own), else Total.
  enum class Mode { PerTriangle, Total, Guides, Auto };
  Mode mode = Mode::Total;  // a scene without a density asks for Auto (Scene::density)
  std::uint32_t strandsPerTriangle = 8;  // Mode::PerTriangle
  std::uint32_t totalStrands = 20000;    // Mode::Total: spread in proportion to triangle area
  std::uint32_t seed = 7;

  void validate() const;  // throws hp::Error: per triangle in [1, 4096], total in [1, 16M]
  bool operator==(const DensityOptions&) const = default;
};

// The fold: (u, v) uniform on the unit square -> uniform on the triangle.
glm::vec3 foldBarycentric(float u, float v);

// Auto resolved for `guides` guides (PerTriangle, Total and Guides are kept).
DensityOptions::Mode resolvedMode(const DensityOptions& density, std::size_t guides);

// Strands per triangle (PerTriangle or Total): PerTriangle gives every triangle the same count; Total gives triangle i
// floor(total * area_i / sum) plus one for the largest remainders, so the counts sum to exactly total.
std::vector<std::uint32_t> strandsPerTriangle(std::span<const glm::vec3> roots,
                                              std::span<const glm::uvec3> triangles,
                                              const DensityOptions& density);

// The triangles' hairline distances are filled in (hairline_distance.h).
// Mode::Guides (or Auto resolving to it): strand g lies on guide g (barycentric 1 at its corner of a triangle
// that has it, or of a triangle (g, g, g) added for a guide in none), in a hashed order so that any prefix
// thins the hair evenly. Throws hp::Error if a triangle names a guide outside roots, or there are no triangles.
InterpolationTopology buildInterpolationTopology(std::span<const glm::vec3> roots,
                                                 std::vector<glm::uvec3> triangles,
                                                 const DensityOptions& density);
}  // namespace hp
