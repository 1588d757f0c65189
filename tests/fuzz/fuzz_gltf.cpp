// glTF 2.0 characters (.gltf text or .glb binary, in memory: no external file is read). Properties of an
// accepted mesh: tests/fuzz/character_mesh_check.h.
#include "engine/core/hair/gltf_mesh.h"
#include "tests/fuzz/character_mesh_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  hp::CharacterMesh m;
  try {
    m = hp::parseGltf({reinterpret_cast<const std::byte*>(data), size}, "fuzz.gltf", {});
  } catch (const hp::Error&) {
    return 0;
  }
  hp::fuzz::checkCharacterMesh(m);
  return 0;
}
