// TressFX .tfxmesh text. Properties of an accepted mesh: tests/fuzz/character_mesh_check.h.
#include <string_view>

#include "engine/core/hair/tfx_mesh_file.h"
#include "tests/fuzz/character_mesh_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  hp::CharacterMesh m;
  try {
    m = hp::parseTfxMesh(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.tfxmesh");
  } catch (const hp::Error&) {
    return 0;
  }
  hp::fuzz::checkCharacterMesh(m);
  return 0;
}
