#include "samples/cli/environment_options.h"

#include <cmath>

#include "engine/core/error.h"
#include "engine/core/shading/environment_lights.h"
#include "samples/tools/environment_file.h"
#include "samples/tools/environment_request.h"

namespace hp::cli {
namespace {
// Every shadow slot but the one the scene's sun keeps.
constexpr std::uint32_t kMaxCliLights = kMaxEnvironmentLights - 1;

std::shared_ptr<const EnvironmentMap> environmentOf(const EnvironmentOptions& o) {
  if (!(o.intensity >= 0.0 && o.intensity <= 1000.0)) throw Error("--environment-intensity must be in [0, 1000]");
  if (!std::isfinite(o.rotationDeg) || std::abs(o.rotationDeg) > 1e6)
    throw Error("--environment-rotation must be a finite angle in degrees");
  if (o.source == "none") return nullptr;
  EnvironmentMap map = o.source == "studio" ? studioEnvironment() : readEnvironmentFile(o.source);
  map.intensity = o.intensity;
  map.rotationDeg = std::fmod(o.rotationDeg, 360.0);
  map.validate();
  return std::make_shared<const EnvironmentMap>(std::move(map));
}
}  // namespace

void addEnvironmentOptions(CLI::App& cmd, EnvironmentOptions& o) {
  cmd.add_option("--environment", o.source,
                 "Environment light: none (the uniform --ambient sky alone), studio (built in: a soft box front left, a "
                 "rim light above and behind) or an equirectangular FILE.hdr / FILE.pfm of linear radiance (row 0 up, "
                 "the middle column along +z); given, --ambient defaults to 0 (default none)");
  cmd.add_option("--environment-intensity", o.intensity, "Environment radiance scale, [0, 1000] (default 1)");
  cmd.add_option("--environment-rotation", o.rotationDeg,
                 "Environment turned about the vertical axis, degrees (counter-clockwise seen from above; default 0)");
  cmd.add_option("--environment-lights", o.lights,
                 "The environment's bright regions drawn as shadowed directional lights, 0..3 (default 2; the rest "
                 "lights the hair and skin through spherical harmonics)");
}

void applyEnvironmentOptions(const EnvironmentOptions& o, RenderRequest& r) {
  if (o.lights > kMaxCliLights) throw Error("--environment-lights must be in [0, " + std::to_string(kMaxCliLights) + "]");
  setEnvironment(r, environmentOf(o), o.lights);
}
}  // namespace hp::cli
