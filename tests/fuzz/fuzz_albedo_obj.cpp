// The head of a frame export (OBJ with per-vertex albedo). Properties of an accepted mesh: one normal and
// one albedo per vertex, whole triangles inside the vertex array (or no vertex and no face: a hair-only
// frame), every value finite, albedos in [0, 1], no zero normal; written back and read again it is
// bit-exact (numbers are printed as the shortest text that reads back to the same float).
#include <cstdint>
#include <string>

#include "engine/core/error.h"
#include "samples/tools/obj_albedo_mesh.h"
#include "tests/fuzz/fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  hp::AlbedoMesh mesh;
  try {
    mesh = hp::parseAlbedoObj(text, "fuzz.obj");
  } catch (const hp::Error&) {
    return 0;
  }
  const std::size_t n = mesh.positions.size();
  HP_FUZZ_REQUIRE(mesh.normals.size() == n && mesh.albedo.size() == n);
  HP_FUZZ_REQUIRE(mesh.indices.size() % 3 == 0);
  HP_FUZZ_REQUIRE(!mesh.indices.empty() || n == 0);
  for (std::uint32_t i : mesh.indices) HP_FUZZ_REQUIRE(i < n);
  for (std::size_t i = 0; i < n; ++i) {
    HP_FUZZ_REQUIRE(hp::fuzz::finite(mesh.positions[i]) && hp::fuzz::finite(mesh.normals[i]));
    const glm::vec3& a = mesh.albedo[i];
    HP_FUZZ_REQUIRE(a.x >= 0.0f && a.y >= 0.0f && a.z >= 0.0f && a.x <= 1.0f && a.y <= 1.0f && a.z <= 1.0f);
    HP_FUZZ_REQUIRE(glm::length(mesh.normals[i]) > 0.0f);
  }
  const hp::AlbedoMesh again = hp::parseAlbedoObj(hp::albedoObjText(mesh), "fuzz.obj (written back)");
  HP_FUZZ_REQUIRE(again.positions == mesh.positions && again.normals == mesh.normals && again.albedo == mesh.albedo &&
                  again.indices == mesh.indices);
  return 0;
}
