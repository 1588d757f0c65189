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

ViewState ViewState::fromScene(const Scene& scene) {
  ViewState s;
  s.camera = scene.camera;
  s.baseDistance = scene.camera.distance;
  const glm::vec3 d = glm::normalize(scene.light.type == LightSpec::Type::Spot
                                         ? scene.light.position - scene.camera.target
                                         : scene.light.direction);
  s.lightElevationDeg = glm::degrees(std::asin(std::clamp(d.y, -1.0f, 1.0f)));
  s.lightAzimuthDeg = glm::degrees(std::atan2(d.x, d.z));
  return s;
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
