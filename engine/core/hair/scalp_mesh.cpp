#include "engine/core/hair/scalp_mesh.h"

#include <algorithm>
#include <cmath>

#include "engine/core/error.h"

namespace hp {
namespace {
float boundingDiagonal(const std::vector<glm::vec3>& positions) {
  glm::vec3 lo(INFINITY), hi(-INFINITY);
  for (const auto& p : positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
  return glm::length(hi - lo);
}

std::vector<glm::vec3> areaWeightedNormals(const ScalpMesh& mesh) {
  std::vector<glm::vec3> normals(mesh.positions.size(), glm::vec3(0.0f));
  for (const auto& t : mesh.triangles) {
    glm::vec3 n = triangleAreaVector(mesh.positions, t);  // length = 2 * area: area weighting
    for (int k = 0; k < 3; ++k) normals[t[k]] += n;
  }
  return normals;
}
}  // namespace

void checkMeshVertices(const std::vector<glm::vec3>& positions, const std::string& source) {
  for (std::size_t i = 0; i < positions.size(); ++i)
    if (!std::isfinite(positions[i].x) || !std::isfinite(positions[i].y) || !std::isfinite(positions[i].z))
      throw Error(source + ": vertex " + std::to_string(i) + " is not finite");
}

void checkMeshIndices(const std::vector<glm::uvec3>& triangles, std::size_t vertexCount, const std::string& source) {
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (int k = 0; k < 3; ++k)
      if (triangles[t][k] >= vertexCount)
        throw Error(source + ": triangle " + std::to_string(t) + " refers to vertex " +
                    std::to_string(triangles[t][k]) + " but there are only " + std::to_string(vertexCount));
}

// Relative threshold: a triangle whose doubled area is below (1e-6 * diagonal)^2 is degenerate.
std::uint32_t dropDegenerateTriangles(const std::vector<glm::vec3>& positions, std::vector<glm::uvec3>& triangles) {
  float diag = boundingDiagonal(positions);
  float minArea2 = (1e-6f * diag) * (1e-6f * diag);
  auto degenerate = [&](const glm::uvec3& t) {
    if (t.x == t.y || t.y == t.z || t.x == t.z) return true;
    return glm::length(triangleAreaVector(positions, t)) <= minArea2;
  };
  auto end = std::remove_if(triangles.begin(), triangles.end(), degenerate);
  auto dropped = static_cast<std::uint32_t>(triangles.end() - end);
  triangles.erase(end, triangles.end());
  return dropped;
}

glm::vec3 triangleAreaVector(const std::vector<glm::vec3>& positions, const glm::uvec3& t) {
  return glm::cross(positions[t.y] - positions[t.x], positions[t.z] - positions[t.x]);
}

ScalpMesh buildScalpMesh(std::vector<glm::vec3> positions, std::vector<glm::uvec3> triangles,
                         std::vector<glm::vec3> normals, const std::string& source) {
  if (!normals.empty() && normals.size() != positions.size())
    throw Error(source + ": " + std::to_string(normals.size()) + " normals for " +
                std::to_string(positions.size()) + " vertices");
  checkMeshVertices(positions, source);
  checkMeshIndices(triangles, positions.size(), source);
  ScalpMesh mesh;
  mesh.positions = std::move(positions);
  mesh.triangles = std::move(triangles);
  mesh.droppedDegenerateTriangles = dropDegenerateTriangles(mesh.positions, mesh.triangles);
  if (mesh.triangles.empty()) throw Error(source + ": no non-degenerate triangles");
  mesh.normals = normals.empty() ? areaWeightedNormals(mesh) : std::move(normals);
  for (std::size_t i = 0; i < mesh.normals.size(); ++i) {
    float len = glm::length(mesh.normals[i]);
    if (!(len > 1e-20f) || !std::isfinite(len))
      throw Error(source + ": vertex " + std::to_string(i) + " has no usable normal (it is in no triangle)");
    mesh.normals[i] /= len;
  }
  return mesh;
}
}  // namespace hp
