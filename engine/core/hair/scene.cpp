// What scene.h declares: LightSpec's spot constructor and the range checks shared by the scene file, the
// CLI and the render job; the light list's checks; RasterMode's names.
#include "engine/core/hair/scene.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "engine/core/error.h"
#include "engine/core/number_text.h"
#include "shaders/shared/render.h"

namespace hp {
namespace {
bool finiteVec(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
}  // namespace

LightSpec LightSpec::makeSpot(const glm::vec3& position, const glm::vec3& target, float coneDeg) {
  LightSpec l;
  l.type = Type::Spot;
  l.position = position;
  l.direction = position - target;  // toward the light; normalised by validate's caller
  const float len = glm::length(l.direction);
  if (!finiteVec(position) || !finiteVec(target)) throw Error("spot position and target must be finite");
  if (!(len > 1e-6f)) throw Error("spot target must differ from its position");
  l.direction /= len;
  l.coneDeg = coneDeg;
  l.validate();
  return l;
}

LightSpec LightSpec::makePoint(const glm::vec3& position, float range) {
  LightSpec l;
  l.type = Type::Point;
  l.position = position;
  l.range = range;
  l.validate();
  return l;
}

void LightSpec::validate() const {
  const float len = glm::length(direction);
  if (!std::isfinite(len) || std::abs(len - 1.0f) > 1e-3f) throw Error("light direction must be a unit vector");
  if (!finiteVec(color) || !glm::all(glm::greaterThanEqual(color, glm::vec3(0.0f))))
    throw Error("light color components must be >= 0");
  if (!(std::isfinite(intensity) && intensity >= 0.0f)) throw Error("light intensity must be >= 0");
  // engine/core/shading/light_limits.h: a directional light's bound (a spot or point light may exceed it
  // nearer than its range, where its falloff grows).
  const float brightest = intensity * std::max({color.r, color.g, color.b});
  if (!(brightest <= kMaxLightRadiance))
    throw Error("light intensity x colour must be at most " + numberText(kMaxLightRadiance) + ", got " +
                numberText(brightest) + " (the radiance images are half floats: scale physical units down)");
  if (type != Type::Directional && type != Type::Spot && type != Type::Point) throw Error("light type is not one of directional, spot, point");
  if (type == Type::Directional) return;
  if (type == Type::Point) {
    if (!finiteVec(position)) throw Error("point light position must be finite");
    if (!(std::isfinite(range) && range >= 0.0f)) throw Error("point light range must be >= 0 (0: no distance falloff)");
    return;
  }
  if (!finiteVec(position)) throw Error("spot position must be finite");
  if (!(coneDeg > 0.0f && coneDeg <= 80.0f)) throw Error("spot coneDeg must be in (0, 80], got " + numberText(coneDeg));
  if (!(std::isfinite(range) && range >= 0.0f)) throw Error("spot range must be >= 0 (0: no distance falloff)");
}
static_assert(kMaxSceneLights == gpu::RENDER_MAX_LIGHTS, "a scene holds what one frame takes");

void validateLights(std::span<const LightSpec> lights) {
  if (lights.size() > kMaxSceneLights)
    throw Error("at most " + std::to_string(kMaxSceneLights) + " lights, got " + std::to_string(lights.size()));
  for (std::size_t i = 0; i < lights.size(); ++i) {
    try {
      lights[i].validate();
    } catch (const Error& e) {
      throw Error("lights[" + std::to_string(i) + "]: " + e.what());
    }
  }
}

std::uint32_t shadowSlotsFor(std::span<const LightSpec> lights) {
  const auto casting = std::count_if(lights.begin(), lights.end(), [](const LightSpec& l) { return l.shadows; });
  // At least one slot: the settings' minimum, and a frame without a shadowed light leaves it unused.
  return std::clamp(std::uint32_t(casting), 1u, gpu::OPACITY_MAX_LIGHTS);
}

const char* lightTypeName(LightSpec::Type type) {
  switch (type) {
    case LightSpec::Type::Directional: return "directional";
    case LightSpec::Type::Spot: return "spot";
    case LightSpec::Type::Point: return "point";
  }
  return "directional";
}

RasterMode parseRasterMode(const std::string& text) {
  if (text == "auto") return RasterMode::Auto;
  if (text == "compute") return RasterMode::Compute;
  if (text == "graphics") return RasterMode::Graphics;
  throw Error("raster must be auto, compute or graphics, got '" + text + "'");
}

const char* rasterModeName(RasterMode mode) {
  switch (mode) {
    case RasterMode::Auto: return "auto";
    case RasterMode::Compute: return "compute";
    case RasterMode::Graphics: return "graphics";
  }
  return "auto";
}
}  // namespace hp
