#include "engine/core/hair/mesh_file.h"

#include <cctype>

#include "engine/core/error.h"
#include "engine/core/hair/gltf_mesh.h"
#include "engine/core/hair/obj_import.h"
#include "engine/core/hair/ply_file.h"
#include "engine/core/hair/tfx_mesh_file.h"

namespace hp {
std::optional<MeshKind> meshKindOf(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  for (auto& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext == ".obj") return MeshKind::Obj;
  if (ext == ".ply") return MeshKind::Ply;
  if (ext == ".gltf" || ext == ".glb") return MeshKind::Gltf;
  if (ext == ".tfxmesh") return MeshKind::TfxMesh;
  return std::nullopt;
}

const char* meshKindName(MeshKind kind) {
  switch (kind) {
    case MeshKind::Obj: return "OBJ";
    case MeshKind::Ply: return "PLY";
    case MeshKind::Gltf: return "glTF";
    case MeshKind::TfxMesh: return "TressFX";
  }
  return "?";
}

namespace {
CharacterMesh objMesh(const std::filesystem::path& path, const ModelTransform& transform) {
  ScalpMesh obj = loadObjScalp(path, transform);
  CharacterMesh m;
  m.source = path.string();
  m.positions = std::move(obj.positions);
  m.normals = std::move(obj.normals);
  m.triangles = std::move(obj.triangles);
  m.droppedDegenerateTriangles = obj.droppedDegenerateTriangles;
  m.modelToHead = transform.matrix();
  finishCharacterMesh(m);
  return m;
}
}  // namespace

CharacterMesh loadCharacterMesh(const std::filesystem::path& path, const ModelTransform& transform) {
  const auto kind = meshKindOf(path);
  if (!kind) throw Error(path.string() + ": not a mesh hairpipe reads (.obj, .ply, .gltf, .glb or .tfxmesh)");
  switch (*kind) {
    case MeshKind::Obj: return objMesh(path, transform);
    case MeshKind::Ply: return readPlyFile(path, transform);
    case MeshKind::Gltf: return readGltfFile(path, transform);
    case MeshKind::TfxMesh: return readTfxMeshFile(path, transform);
  }
  throw Error(path.string() + ": unknown mesh kind");
}
}  // namespace hp
