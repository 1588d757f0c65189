#include "samples/tools/host/head_animation.h"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "engine/core/error.h"

namespace hp {
namespace {
constexpr double kPi = 3.14159265358979323846;
// Rotations pivot at the top of the neck, a little below and behind the cranium center.
const glm::vec3 kNeckPivot{0.0f, -0.09f, -0.01f};

glm::mat4 rotateAboutPivot(float radians, const glm::vec3& axis) {
  glm::mat4 m = glm::translate(glm::mat4(1.0f), kNeckPivot);
  m = glm::rotate(m, radians, axis);
  return glm::translate(m, -kNeckPivot);
}

double oscillation(double amplitudeDeg, double hz, double t) {
  return glm::radians(amplitudeDeg) * std::sin(2.0 * kPi * hz * t);
}
}  // namespace

HeadAnimation parseHeadAnimation(const std::string& name) {
  if (name == "none") return HeadAnimation::None;
  if (name == "nod") return HeadAnimation::Nod;
  if (name == "turn") return HeadAnimation::Turn;
  if (name == "shake") return HeadAnimation::Shake;
  if (name == "teleport") return HeadAnimation::Teleport;
  throw Error("unknown head animation '" + name + "' (choose none, nod, turn, shake or teleport)");
}

const char* headAnimationName(HeadAnimation animation) {
  switch (animation) {
    case HeadAnimation::None: return "none";
    case HeadAnimation::Nod: return "nod";
    case HeadAnimation::Turn: return "turn";
    case HeadAnimation::Shake: return "shake";
    case HeadAnimation::Teleport: return "teleport";
  }
  return "none";
}

glm::mat4 headTransformAt(HeadAnimation animation, double t, float headRadius) {
  switch (animation) {
    case HeadAnimation::None: return glm::mat4(1.0f);
    case HeadAnimation::Nod: return rotateAboutPivot(float(oscillation(20.0, 0.5, t)), {1, 0, 0});
    case HeadAnimation::Turn: return rotateAboutPivot(float(oscillation(60.0, 0.25, t)), {0, 1, 0});
    case HeadAnimation::Shake: return rotateAboutPivot(float(oscillation(35.0, 2.5, t)), {0, 1, 0});
    case HeadAnimation::Teleport: {
      bool away = t >= 1.0 && t < 2.0;
      return glm::translate(glm::mat4(1.0f), glm::vec3(away ? 10.0f * headRadius : 0.0f, 0.0f, 0.0f));
    }
  }
  return glm::mat4(1.0f);
}

bool headTeleportsBetween(HeadAnimation animation, double t0, double t1) {
  if (animation != HeadAnimation::Teleport) return false;
  auto crosses = [&](double edge) { return t0 < edge && t1 >= edge; };
  return crosses(1.0) || crosses(2.0);
}
}  // namespace hp
