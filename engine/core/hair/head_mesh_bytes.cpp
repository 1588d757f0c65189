#include "engine/core/hair/head_mesh_bytes.h"

#include "engine/core/hair/head_mesh.h"

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
  requireMeshShape(mesh, "head mesh bytes");
  return mesh;
}
}  // namespace hp
