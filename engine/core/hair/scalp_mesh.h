#pragma once
// Contract: the scalp guides grow from (paper §1): vertex positions, unit vertex normals, and
// triangles of vertex indices. One guide grows per vertex; the triangles become the interpolation
// topology. The scalp itself is never drawn. Built only through buildScalpMesh, which guarantees:
// every index is in range, no triangle is degenerate, every normal is unit length.
#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace hp {
struct ScalpMesh {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;      // one per position, unit length
  std::vector<glm::uvec3> triangles;   // counter-clockwise seen from outside
  std::uint32_t droppedDegenerateTriangles = 0;  // zero-area input triangles removed by the build

  std::uint32_t vertexCount() const { return static_cast<std::uint32_t>(positions.size()); }
};

// Checks indices (hp::Error naming `source`), drops zero-area triangles and counts them, and computes
// area-weighted normals when `normals` is empty (given normals are normalized). Throws if no triangle
// is left or a vertex ends up without a usable normal (in no triangle and none given).
ScalpMesh buildScalpMesh(std::vector<glm::vec3> positions, std::vector<glm::uvec3> triangles,
                         std::vector<glm::vec3> normals = {}, const std::string& source = "scalp");

// hp::Error naming `source` for a vertex that is not finite, or a triangle index past vertexCount.
void checkMeshVertices(const std::vector<glm::vec3>& positions, const std::string& source);
void checkMeshIndices(const std::vector<glm::uvec3>& triangles, std::size_t vertexCount, const std::string& source);

// Removes zero-area triangles (relative to the mesh size) and returns how many it removed.
std::uint32_t dropDegenerateTriangles(const std::vector<glm::vec3>& positions, std::vector<glm::uvec3>& triangles);

// Twice the area vector of triangle t (cross product of two edges).
glm::vec3 triangleAreaVector(const std::vector<glm::vec3>& positions, const glm::uvec3& t);
}  // namespace hp
