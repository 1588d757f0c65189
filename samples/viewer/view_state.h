#pragma once
// Contract: what the viewer's user controls, and how mouse and keys change it. Pure host state, no
// GLFW: the window's callbacks translate events into these calls (viewer_app.cpp), so the mapping is
// testable. Mouse: left drag orbits the camera (horizontal: orbit, vertical: elevation, clamped to
// +-85 deg), the wheel zooms (distance x 0.9 per notch, clamped), a left drag with Shift (or a right
// drag) turns the light. Keys: N nod, T turn, S shake (the same key again stops it), W wind on/off,
// Space pause, F1 or Tab panel, Escape or Q close.
#include "engine/core/hair/scene.h"
#include "samples/tools/host/head_animation.h"

namespace hp::viewer {
enum class Key { Nod, Turn, Shake, Wind, Pause, Panel, Close, Other };

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

  // Camera and light from a scene (the light's direction becomes azimuth/elevation).
  static ViewState fromScene(const Scene& scene);
  void drag(float dxPixels, float dyPixels, bool light);
  void scroll(float notches);
  void key(Key key);
  glm::vec3 lightDirection() const;  // unit, toward the light
};
}  // namespace hp::viewer
