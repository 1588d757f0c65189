// OBJ scalps. Properties of an accepted mesh: at least one triangle, every index inside the vertex
// array, every position and normal finite; and no file is ever opened (parsed from memory).
#include <cstdint>
#include <string>

#include "engine/core/error.h"
#include "engine/core/hair/obj_import.h"
#include "tests/fuzz/fuzz_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  hp::ScalpMesh mesh;
  try {
    mesh = hp::parseObjScalp(text, "fuzz.obj");
  } catch (const hp::Error&) {
    return 0;
  }
  HP_FUZZ_REQUIRE(!mesh.triangles.empty());
  const std::size_t n = mesh.positions.size();
  for (const auto& t : mesh.triangles) HP_FUZZ_REQUIRE(t.x < n && t.y < n && t.z < n);
  for (const auto& p : mesh.positions) HP_FUZZ_REQUIRE(hp::fuzz::finite(p));
  HP_FUZZ_REQUIRE(mesh.normals.size() == n);
  for (const auto& v : mesh.normals) HP_FUZZ_REQUIRE(hp::fuzz::finite(v));
  return 0;
}
