#include "samples/viewer/view_state.h"

#include <algorithm>
#include <cmath>

namespace hp::viewer {
namespace {
constexpr float kDegreesPerPixel = 0.4f;
constexpr float kMaxElevation = 85.0f;
constexpr float kZoomPerNotch = 0.9f;

void toggle(ViewState& s, HeadAnimation a) {
  s.animation = s.animation == a ? HeadAnimation::None : a;
  s.animationChanged = true;
}
}  // namespace

std::vector<EditedLight> editableLights(const Scene& scene) {
  std::vector<EditedLight> out;
  for (const LightSpec& l : scene.lights) {
    EditedLight e{l, scene.camera.target};
    if (l.type == LightSpec::Type::Spot)
      e.target = l.position - l.direction * std::max(glm::length(l.position - scene.camera.target), 1e-3f);
    out.push_back(e);
  }
  return out;
}

ViewState ViewState::fromScene(const Scene& scene) {
  ViewState s;
  s.camera = scene.camera;
  s.baseDistance = scene.camera.distance;
  const std::vector<EditedLight> lights = editableLights(scene);
  if (!lights.empty()) s.aimLight(s.towardLightOf(lights.front()));
  return s;
}

glm::vec3 ViewState::aimCentre(const EditedLight& l) const {
  return l.light.type == LightSpec::Type::Spot ? l.target : camera.target;
}

glm::vec3 ViewState::towardLightOf(const EditedLight& l) const {
  if (l.light.type == LightSpec::Type::Directional) return glm::normalize(l.light.direction);
  const glm::vec3 d = l.light.position - aimCentre(l);
  return glm::length(d) > 1e-6f ? glm::normalize(d) : glm::normalize(l.light.direction);
}

void ViewState::aimLight(const glm::vec3& towardLight) {
  const glm::vec3 d = glm::normalize(towardLight);
  lightElevationDeg = glm::degrees(std::asin(std::clamp(d.y, -1.0f, 1.0f)));
  lightAzimuthDeg = glm::degrees(std::atan2(d.x, d.z));
}

void ViewState::steer(EditedLight& l) const {
  const glm::vec3 toward = lightDirection();
  if (l.light.type == LightSpec::Type::Directional) {
    l.light.direction = toward;
    return;
  }
  const glm::vec3 centre = aimCentre(l);
  const float distance = glm::length(l.light.position - centre);
  if (!(distance > 1e-6f)) return;  // on its centre: no sphere to move on
  l.light.position = centre + toward * distance;
  if (l.light.type == LightSpec::Type::Spot) l.light.direction = toward;  // still aimed at its target
}

void ViewState::drag(float dx, float dy, bool light) {
  float& azimuth = light ? lightAzimuthDeg : camera.orbitDeg;
  float& elevation = light ? lightElevationDeg : camera.elevationDeg;
  azimuth = std::fmod(azimuth - dx * kDegreesPerPixel, 360.0f);
  elevation = std::clamp(elevation + dy * kDegreesPerPixel, -kMaxElevation, kMaxElevation);
}

void ViewState::scroll(float notches) {
  // Closer than a tenth of the starting framing is inside the head; farther than 20x is a dot.
  camera.distance = std::clamp(camera.distance * std::pow(kZoomPerNotch, notches), 0.1f * baseDistance,
                               20.0f * baseDistance);
}

void ViewState::key(Key k) {
  switch (k) {
    case Key::Nod: toggle(*this, HeadAnimation::Nod); break;
    case Key::Turn: toggle(*this, HeadAnimation::Turn); break;
    case Key::Shake: toggle(*this, HeadAnimation::Shake); break;
    case Key::Wind: wind = !wind; break;
    case Key::Pause: paused = !paused; break;
    case Key::Panel: panel = !panel; break;
    case Key::Close: close = true; break;
    case Key::Other: break;
  }
}

glm::vec3 ViewState::lightDirection() const {
  const float a = glm::radians(lightAzimuthDeg), e = glm::radians(lightElevationDeg);
  return {std::cos(e) * std::sin(a), std::sin(e), std::cos(e) * std::cos(a)};
}
}  // namespace hp::viewer
