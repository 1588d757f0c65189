#include "engine/core/hair/head_mesh_bytes.h"

#include <string>

namespace hp {
static_assert(sizeof(glm::vec3) == 3 * sizeof(float), "positions and normals are written as packed floats");

void writeHeadMesh(ByteWriter& out, const HeadMesh& mesh) {
  out.putVector(mesh.positions);
  out.putVector(mesh.normals);
  out.putVector(mesh.indices);
  out.putVector(mesh.scalp);
}

HeadMesh readHeadMesh(ByteReader& in) {
  HeadMesh mesh;
  mesh.positions = in.getVector<glm::vec3>("positions");
  mesh.normals = in.getVector<glm::vec3>("normals");
  mesh.indices = in.getVector<std::uint32_t>("indices");
  mesh.scalp = in.getVector<float>("scalp weights");
  const std::size_t n = mesh.positions.size();
  if (mesh.normals.size() != n || (!mesh.scalp.empty() && mesh.scalp.size() != n) || mesh.indices.size() % 3 != 0)
    throw Error("head mesh bytes: " + std::to_string(n) + " positions with " + std::to_string(mesh.normals.size()) +
                " normals, " + std::to_string(mesh.scalp.size()) + " scalp weights and " +
                std::to_string(mesh.indices.size()) + " indices");
  for (std::uint32_t i : mesh.indices)
    if (i >= n) throw Error("head mesh bytes: index " + std::to_string(i) + " of " + std::to_string(n) + " positions");
  return mesh;
}
}  // namespace hp
