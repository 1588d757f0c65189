#include "engine/hair/head_mesh.h"

#include <algorithm>
#include <limits>

#include <cmath>

namespace hp {
HeadMesh makeEllipsoidMesh(const glm::vec3& center, const glm::vec3& radii, std::uint32_t slices,
                           std::uint32_t stacks) {
  HeadMesh m;
  const float pi = 3.14159265358979f;
  for (std::uint32_t i = 0; i <= stacks; ++i) {
    float theta = pi * float(i) / float(stacks);  // 0 at +Y
    for (std::uint32_t j = 0; j <= slices; ++j) {
      float phi = 2.0f * pi * float(j) / float(slices);
      glm::vec3 unit(std::sin(theta) * std::sin(phi), std::cos(theta), std::sin(theta) * std::cos(phi));
      m.positions.push_back(center + unit * radii);
      m.normals.push_back(glm::normalize(unit / radii));  // ellipsoid normal: gradient of |x/r|^2
    }
  }
  const std::uint32_t row = slices + 1;
  for (std::uint32_t i = 0; i < stacks; ++i)
    for (std::uint32_t j = 0; j < slices; ++j) {
      std::uint32_t a = i * row + j, b = a + row, c = b + 1, d = a + 1;
      if (i != 0) m.indices.insert(m.indices.end(), {a, b, d});
      if (i + 1 != stacks) m.indices.insert(m.indices.end(), {d, b, c});
    }
  return m;
}

void appendMesh(HeadMesh& into, const HeadMesh& part) {
  auto base = static_cast<std::uint32_t>(into.positions.size());
  into.positions.insert(into.positions.end(), part.positions.begin(), part.positions.end());
  into.normals.insert(into.normals.end(), part.normals.begin(), part.normals.end());
  for (std::uint32_t i : part.indices) into.indices.push_back(base + i);
}
namespace {
// Nearest distance from p to any root except index `skip`.
float nearestRoot(const glm::vec3& p, std::span<const glm::vec3> roots, std::size_t skip) {
  float best = std::numeric_limits<float>::infinity();
  for (std::size_t i = 0; i < roots.size(); ++i)
    if (i != skip) best = std::min(best, glm::length(roots[i] - p));
  return best;
}

float meanRootSpacing(std::span<const glm::vec3> roots) {
  const std::size_t samples = std::min<std::size_t>(roots.size(), 256);
  const std::size_t stride = roots.size() / samples;
  double sum = 0.0;
  for (std::size_t k = 0; k < samples; ++k) sum += nearestRoot(roots[k * stride], roots, k * stride);
  return float(sum / double(samples));
}
}  // namespace

void markScalp(HeadMesh& mesh, std::span<const glm::vec3> roots) {
  mesh.scalp.assign(mesh.positions.size(), 0.0f);
  if (roots.size() < 2) return;
  const float spacing = meanRootSpacing(roots);
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    const float d = nearestRoot(mesh.positions[v], roots, roots.size());
    mesh.scalp[v] = 1.0f - glm::smoothstep(spacing, 3.0f * spacing, d);
  }
}
}  // namespace hp
