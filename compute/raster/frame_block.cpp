#include "compute/raster/frame_block.h"

#include <algorithm>
#include <cmath>

#include "engine/core/error.h"
#include "engine/core/shading/environment_sh.h"
#include "shaders/shared/light.h"
#include "shaders/shared/marschner.h"

namespace hp::render {
namespace {
constexpr float kSpotInnerFraction = 0.8f;  // full radiance inside 80% of the half-angle (shaders/shared/light.h)
constexpr float kMaxEnvironmentCoefficient = 1e4f;  // a sky of radiance ~2800: far beyond any real light
}  // namespace

const char* scatteringName(Scattering s) { return s == Scattering::Dual ? "dual" : "single"; }

Scattering parseScattering(const std::string& text) {
  if (text == "single") return Scattering::Single;
  if (text == "dual") return Scattering::Dual;
  throw Error("scattering must be single or dual, got '" + text.substr(0, 40) + "'");
}

void LookSettings::validate() const {
  auto positiveFinite = [](float v) { return std::isfinite(v) && v > 0.0f; };
  if (!positiveFinite(strandWidth) || strandWidth > 0.01f) throw Error("strand width must be in (0, 0.01] scene units");
  if (!(tipWidthFraction >= 0.0f && tipWidthFraction <= 1.0f)) throw Error("tip width fraction must be in [0, 1]");
  if (!(wrap >= 0.0f && wrap <= 1.0f)) throw Error("wrap must be in [0, 1]");
  if (!(ambient >= 0.0f && ambient <= 10.0f)) throw Error("ambient must be in [0, 10]");
  for (const glm::vec3& c : environment)
    for (int i = 0; i < 3; ++i)
      if (!(std::abs(c[i]) <= kMaxEnvironmentCoefficient))
        throw Error("environment coefficients must be finite and within +-10000");
  if (scattering != Scattering::Single && scattering != Scattering::Dual) throw Error("scattering must be Single or Dual");
  for (int i = 0; i < 3; ++i)
    if (!(skinColor[i] >= 0.0f && skinColor[i] <= 1.0f)) throw Error("skin colour components must be in [0, 1]");
}

namespace {
gpu::FrameLight frameLight(const LightSpec& light, int slot) {
  gpu::FrameLight f{};
  f.direction = glm::vec4(glm::normalize(light.direction), float(slot));
  f.radiance = glm::vec4(light.color * light.intensity, 0.0f);
  if (light.type == LightSpec::Type::Directional) return f;
  const bool spot = light.type == LightSpec::Type::Spot;
  f.position = glm::vec4(light.position, spot ? gpu::RENDER_LIGHT_SPOT : gpu::RENDER_LIGHT_POINT);
  const float cone = glm::radians(light.coneDeg);
  f.spot = spot ? glm::vec4(std::cos(cone), std::cos(kSpotInnerFraction * cone), light.range, 0.0f)
                : glm::vec4(0.0f, 0.0f, light.range, 0.0f);
  return f;
}

void setLights(gpu::RenderFrame& f, const FrameLights& lights, bool skinBounce) {
  f.lightCount = glm::uvec4(std::uint32_t(lights.lights.size()), 0u, 0u, 0u);
  for (std::size_t i = 0; i < lights.lights.size(); ++i) f.lights[i] = frameLight(lights.lights[i], lights.slots[i]);
  for (std::uint32_t s = 0; s < gpu::OPACITY_MAX_LIGHTS; ++s)
    f.shadows[s] = {lights.headViews[s].viewProj, lights.headViews[s].params};
  const int bounceLight = lights.lightOfSlot(0);
  const HeadShadowView& view = lights.headViews[0];
  const bool on = skinBounce && bounceLight >= 0 && view.params.x != 0.0f;
  // The bounce map's light whenever slot 0 has one (the map's draw reads it for every head, whatever its
  // look); headBounce.x alone says whether this instance's hair gathers from the map.
  f.lightCount.y = bounceLight >= 0 ? std::uint32_t(bounceLight) : gpu::RENDER_MAX_LIGHTS;
  f.headBounce = glm::vec4(on ? 1.0f : 0.0f, view.extentWorld / float(gpu::RENDER_BOUNCE_RESOLUTION), 0.0f, 0.0f);
}
// The sky's radiance SH in world axes: the environment's plus the uniform ambient.
EnvironmentSH skyRadiance(const LookSettings& look) {
  EnvironmentSH radiance = uniformEnvironmentSH(glm::dvec3(look.ambient));
  for (std::size_t i = 0; i < radiance.size(); ++i) radiance[i] += glm::dvec3(look.environment[i]);
  return radiance;
}

// The sky convolved for the shaders (shared/environment.h).
void setEnvironment(gpu::RenderFrame& f, const LookSettings& look) {
  const EnvironmentSH convolved = cosineConvolved(skyRadiance(look));
  for (std::size_t i = 0; i < convolved.size(); ++i) f.environment[i] = glm::vec4(glm::vec3(convolved[i]), 0.0f);
}
}  // namespace

glm::vec4 hairForward(const LookSettings& look, const glm::vec3& forwardAlbedo) {
  return look.scattering == Scattering::Dual ? glm::vec4(forwardAlbedo, gpu::MARSCHNER_FORWARD_DENSITY) : glm::vec4(0.0f);
}

gpu::RenderFrame makeRenderFrame(const CameraMatrices& camera, VkExtent2D extent, const FrameLights& lights,
                                 const HairMaterial& material, const LookSettings& look,
                                 const compute::StrandLayout& strands, const OpacitySettings& opacity,
                                 const glm::vec3& forwardAlbedo) {
  gpu::RenderFrame f{};
  f.view = camera.view;
  f.proj = camera.proj;
  const float pixelAtUnitDepth = 2.0f * std::tan(0.5f * camera.fovY) / float(extent.height);
  f.cameraPosition = glm::vec4(camera.position, pixelAtUnitDepth);
  setLights(f, lights, look.skinBounce);
  f.headBounce.z = float(strands.bounceSamples);
  f.headBounce.w = look.farSideFromDepth ? 1.0f : 0.0f;
  f.previousViewProj = camera.proj * camera.view;  // no motion until setViewMotion says otherwise
  // The colour of one straight pass through the fibre (absorptionFromColor's inverse) as ambient albedo.
  const glm::dvec3 albedo = glm::exp(-2.0 * material.absorption);
  f.hairColor = glm::vec4(glm::vec3(albedo), 0.0f);
  setEnvironment(f, look);
  f.skinColor = glm::vec4(look.skinColor, look.wrap);
  f.hairForward = hairForward(look, forwardAlbedo);
  f.strand = glm::vec4(look.strandWidth, look.tipWidthFraction, opacity.k, lookupBias(opacity));
  f.options = glm::uvec4(strands.verticesPerStrand, opacity.enabled ? 1u : 0u,
                         look.scattering == Scattering::Dual ? gpu::RENDER_SCATTERING_DUAL : gpu::RENDER_SCATTERING_SINGLE,
                         opacity.deep ? 1u : 0u);
  return f;
}

namespace {
void store(glm::vec4 (&into)[gpu::ENV_SH_COEFFICIENTS], const EnvironmentSH& sh) {
  for (std::size_t i = 0; i < sh.size(); ++i) into[i] = glm::vec4(glm::vec3(sh[i]), 0.0f);
}
}  // namespace

void setSkinLight(gpu::RenderFrame& f, const glm::mat4& headToWorld, const glm::vec3& headCentre,
                  const FrameLights& lights, const LookSettings& look) {
  if (!look.skinIndirect) {
    f.skinSky[0].w = 0.0f;
    return;
  }
  const glm::dmat3 m(headToWorld);
  const glm::dmat3 rotation(glm::normalize(m[0]), glm::normalize(m[1]), glm::normalize(m[2]));
  store(f.skinSky, rotateEnvironment(skyRadiance(look), rotation));
  f.skinSky[0].w = 1.0f;
  EnvironmentSH light{};
  for (const LightSpec& spec : lights.lights) {
    const gpu::LightSample arriving = gpu::sampleLight(frameLight(spec, -1), headCentre);
    if (arriving.scale > 0.0f)
      addToEnvironment(light, glm::transpose(rotation) * glm::dvec3(arriving.L),
                       glm::dvec3(spec.color * (spec.intensity * arriving.scale)));
  }
  store(f.skinLights, light);
}

void setViewMotion(gpu::RenderFrame& frame, VkExtent2D extent, const glm::vec2& jitter,
                   const std::optional<glm::mat4>& previousViewProj) {
  if (previousViewProj) frame.previousViewProj = *previousViewProj;
  frame.jitter = glm::vec4(jitter, 0.0f, 0.0f);
  // clip.xy += (2 j.x / width, -2 j.y / height) clip.w: pixel rows go down, clip +Y up.
  glm::mat4 shift(1.0f);
  shift[3][0] = 2.0f * jitter.x / float(extent.width);
  shift[3][1] = -2.0f * jitter.y / float(extent.height);
  frame.proj = shift * frame.proj;
}
}  // namespace hp::render
