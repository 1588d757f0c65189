#pragma once
// Contract: what the viewer's user controls, and how mouse and keys change it. Pure host state, no
// GLFW: the window's callbacks translate events into these calls (viewer_app.cpp), so the mapping is
// testable. Mouse: left drag orbits the camera (horizontal: orbit, vertical: elevation, clamped to
// +-85 deg), the wheel zooms (distance x 0.9 per notch, clamped), a left drag with Shift (or a right
// drag) turns the first light (its direction, or a spot's or point light's position around what it aims
// at). Keys: N nod, T turn, S shake (the same key again stops it), W wind on/off,
// Space pause, F1 or Tab panel, Escape or Q close.
#include <vector>

#include "engine/core/hair/scene.h"
#include "samples/tools/host/head_animation.h"

namespace hp::viewer {
enum class Key { Nod, Turn, Shake, Wind, Pause, Panel, Close, Other };

// One light as the panel edits it: the LightSpec, and for a spot the point it aims at (a LightSpec keeps
// only the spot's direction).
struct EditedLight {
  LightSpec light;
  glm::vec3 target{0.0f};  // spot: where it aims
};
// The scene's lights for editing; a spot's target is put on its axis at the camera target's distance.
std::vector<EditedLight> editableLights(const Scene& scene);

struct ViewState {
  CameraSpec camera;
  float lightAzimuthDeg = 0.0f;    // around +Y from +Z, like the camera's orbit
  float lightElevationDeg = 45.0f;
  HeadAnimation animation = HeadAnimation::None;
  bool animationChanged = false;   // set by a key; the frame loop restarts the animation clock
  bool wind = false;
  bool paused = false;
  bool panel = true;
  bool close = false;
  float baseDistance = 1.0f;      // the scene's framing: zoom stays within [0.1, 20] x this

  // Camera and light from a scene (the first light's direction from its aim centre becomes azimuth/elevation).
  static ViewState fromScene(const Scene& scene);
  void drag(float dxPixels, float dyPixels, bool light);
  void scroll(float notches);
  void key(Key key);
  glm::vec3 lightDirection() const;  // unit, toward the light: what the light drag sets

  // What a light turns around: a spot its target, a point light the camera target (a directional light
  // only has a direction).
  glm::vec3 aimCentre(const EditedLight& l) const;
  // Unit, from the aim centre toward the light (a directional light's direction).
  glm::vec3 towardLightOf(const EditedLight& l) const;
  // The drag's azimuth/elevation set to point along `towardLight` (after the panel moved the first light).
  void aimLight(const glm::vec3& towardLight);
  // The first light turned to lightDirection(): a directional light's direction; a spot's or point light's
  // position on the sphere around aimCentre through it (a spot stays aimed at its target).
  void steer(EditedLight& l) const;
};
}  // namespace hp::viewer
