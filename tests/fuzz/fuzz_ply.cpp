// Stanford PLY meshes (ascii and both binary byte orders). Properties of an accepted mesh:
// tests/fuzz/character_mesh_check.h.
#include "engine/core/hair/ply_file.h"
#include "tests/fuzz/character_mesh_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  hp::CharacterMesh m;
  try {
    m = hp::parsePly({reinterpret_cast<const std::byte*>(data), size}, "fuzz.ply");
  } catch (const hp::Error&) {
    return 0;
  }
  hp::fuzz::checkCharacterMesh(m);
  return 0;
}
