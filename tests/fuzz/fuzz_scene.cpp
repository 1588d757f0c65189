// Scene JSON. Properties of an accepted scene: every section passes its own validate() again and
// every number it holds is finite (nothing overflowed on its way into a float).
#include <cstdint>
#include <string>

#include "engine/core/error.h"
#include "engine/core/hair/scene.h"
#include "samples/tools/host/scene_file.h"
#include "tests/fuzz/fuzz_check.h"

namespace {
void checkScene(const hp::Scene& s) {
  s.model.transform.validate();
  s.growth.validate();
  s.density.validate();
  s.material.validate();
  hp::validateLights(s.lights);
  s.simulation.validate();
  s.groom.validate();
  for (const hp::LightSpec& l : s.lights)
    HP_FUZZ_REQUIRE(hp::fuzz::finite(l.direction) && hp::fuzz::finite(l.position) && hp::fuzz::finite(l.color));
  HP_FUZZ_REQUIRE(hp::fuzz::finite(s.camera.target) && std::isfinite(s.camera.distance) && s.camera.distance > 0.0f);
  HP_FUZZ_REQUIRE(std::isfinite(s.camera.orbitDeg) && std::isfinite(s.camera.fovDeg));
  HP_FUZZ_REQUIRE(s.render.width >= 1 && s.render.width <= 16384 && s.render.height >= 1 && s.render.height <= 16384);
  if (s.colliders)
    for (const auto& c : *s.colliders) HP_FUZZ_REQUIRE(hp::fuzz::finite(c.center) && c.radius > 0.0f && std::isfinite(c.radius));
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  hp::Scene scene;
  try {
    scene = hp::parseScene(text, "fuzz.json", "/nonexistent");
  } catch (const hp::Error&) {
    return 0;
  }
  try {
    checkScene(scene);
  } catch (const hp::Error& e) {
    hp::fuzz::violated(e.what(), __FILE__, __LINE__);  // accepted, yet a section is invalid
  }
  return 0;
}
