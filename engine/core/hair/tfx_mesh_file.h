#pragma once
// Contract: AMD TressFX collision/character meshes (.tfxmesh, docs/THEORY.md §8.4): text, '#' comments,
// "numOfBones N" and N lines "index name", "numOfVertices N" and N lines "index x y z nx ny nz j0 j1 j2 j3
// w0 w1 w2 w3" (joints index the file's bone list), "numOfTriangles N" and N lines "index a b c". Every count
// is checked against the lines left before anything is allocated, every index against its list, every
// number for being one; the first problem is refused by hp::Error naming the source, the line and the field.
// The bones become a skeleton of named joints without a hierarchy or bind pose (the application skins them
// with its own bone matrices, as TressFX does); then finishCharacterMesh checks the rest.
#include <filesystem>
#include <string>
#include <string_view>

#include "engine/core/hair/character_mesh.h"
#include "engine/core/hair/model_transform.h"

namespace hp {
CharacterMesh parseTfxMesh(std::string_view text, const std::string& source, const ModelTransform& transform = {});
CharacterMesh readTfxMeshFile(const std::filesystem::path& path, const ModelTransform& transform = {});
}  // namespace hp
