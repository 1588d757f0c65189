#pragma once
// Contract: Stanford PLY meshes (ascii, binary_little_endian and binary_big_endian 1.0): the "vertex"
// element's x, y, z (and nx, ny, nz when all three are there) and the "face" element's vertex_indices
// (or vertex_index) list, polygons fan-triangulated; every other element and property is read and skipped.
// The header is at most 64 KiB; every element's count is checked against the bytes left (at its smallest
// record size) before anything is allocated; every index against the vertices, polygons to 3..1024 corners;
// the first problem is refused by hp::Error naming the source and the element, record and property.
// Then finishCharacterMesh checks the rest (a PLY mesh is rigid: no skin).
#include <filesystem>
#include <span>
#include <string>

#include "engine/core/hair/character_mesh.h"
#include "engine/core/hair/model_transform.h"

namespace hp {
CharacterMesh parsePly(std::span<const std::byte> bytes, const std::string& source, const ModelTransform& transform = {});
CharacterMesh readPlyFile(const std::filesystem::path& path, const ModelTransform& transform = {});
}  // namespace hp
