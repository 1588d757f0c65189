#include "engine/hair/head_mesh.h"

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
}  // namespace hp
