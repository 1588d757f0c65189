#pragma once
// Contract: a character from glTF 2.0 (.gltf with its buffers, or .glb; parsed by tinygltf, docs/THEORY.md
// §8.5): every triangle primitive of the meshes the default scene's nodes instance, in model space (a rigid
// mesh placed by its node's rest transform; a skinned one in its bind space, as glTF defines), merged into one
// CharacterMesh with its transform applied. One skin per file: its joints become the skeleton (parents
// first), JOINTS_0 / WEIGHTS_0 the vertices' weights; a rigid primitive of a skinned file follows its
// nearest joint ancestor, or none. Animation channels that drive the skin's joints (translation, rotation,
// scale) become clips; cubic-spline keys keep their values and are read linearly. Images, materials, morph
// targets, cameras and other animation targets are ignored; points and lines are skipped; strips and fans
// are triangulated. External buffers are read only inside the file's folder, through hairpipe's input door
// (none for in-memory input). Refused by hp::Error naming the source: what tinygltf cannot parse, a second
// skin, node graphs with cycles or shared children, sparse or out-of-bounds accessors, then what
// finishCharacterMesh checks.
#include <cstddef>
#include <filesystem>
#include <span>
#include <string>

#include "engine/core/hair/character_mesh.h"
#include "engine/core/hair/model_transform.h"

namespace hp {
// `folder`: where external buffers may be read from; empty reads none.
CharacterMesh parseGltf(std::span<const std::byte> bytes, const std::string& source, const std::filesystem::path& folder,
                        const ModelTransform& transform = {});
CharacterMesh readGltfFile(const std::filesystem::path& path, const ModelTransform& transform = {});
}  // namespace hp
