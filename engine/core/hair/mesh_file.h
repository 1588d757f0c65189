#pragma once
// Contract: a character mesh from a file of any kind hairpipe reads, chosen by its extension (any case):
// .obj (rigid; OBJ scalp rules: obj_import.h), .ply, .gltf / .glb, .tfxmesh. Every reader goes through
// hairpipe's input door and refuses by hp::Error naming the file; meshKindOf says which kind a path names.
#include <filesystem>
#include <optional>

#include "engine/core/hair/character_mesh.h"
#include "engine/core/hair/model_transform.h"

namespace hp {
enum class MeshKind { Obj, Ply, Gltf, TfxMesh };
std::optional<MeshKind> meshKindOf(const std::filesystem::path& path);
const char* meshKindName(MeshKind kind);
CharacterMesh loadCharacterMesh(const std::filesystem::path& path, const ModelTransform& transform = {});
}  // namespace hp
