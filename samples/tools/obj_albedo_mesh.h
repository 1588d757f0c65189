#pragma once
// Contract: a triangle mesh with one normal and one albedo per vertex as a Wavefront OBJ with vertex
// colours ("v x y z r g b", "vn x y z", "f a//a b//b c//c", 1-based, normal i belongs to vertex i), the
// head of a frame export. Numbers are printed as the shortest text that reads back to the same float.
// readAlbedoObj accepts exactly that subset (comments and blank lines aside) and throws hp::Error
// naming the file and line for anything else; writeAlbedoObj is atomic. A file with no vertex and no face
// is the empty head of a hair-only frame.
#include <glm/glm.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace hp {
struct AlbedoMesh {
  std::vector<glm::vec3> positions, normals, albedo;
  std::vector<std::uint32_t> indices;  // triangle list
};

void writeAlbedoObj(const std::filesystem::path& path, const AlbedoMesh& mesh);
AlbedoMesh readAlbedoObj(const std::filesystem::path& path);
// The same in memory: the file's text, and a text parsed (`source` names it in messages).
std::string albedoObjText(const AlbedoMesh& mesh);
AlbedoMesh parseAlbedoObj(const std::string& text, const std::string& source);
}  // namespace hp
