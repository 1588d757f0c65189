#pragma once
// Contract: scripted head motions for the CLI, tests and benchmarks: the head-to-world transform at
// any time t (seconds). Pure functions, no state, so a frame's motion is headAt(t0) -> headAt(t1).
//   none      the head stays at the origin
//   nod       pitch +-20 deg at 0.5 Hz around the neck
//   turn      yaw +-60 deg at 0.25 Hz
//   shake     yaw +-35 deg at 2.5 Hz: fast back-and-forth that makes long hair swing
//   teleport  still, but jumps by 10 head radii along +X at t = 1 s (and back at t = 2 s)
#include <glm/glm.hpp>

#include <string>

namespace hp {
enum class HeadAnimation { None, Nod, Turn, Shake, Teleport };

HeadAnimation parseHeadAnimation(const std::string& name);  // throws hp::Error listing the choices
const char* headAnimationName(HeadAnimation animation);
glm::mat4 headTransformAt(HeadAnimation animation, double seconds, float headRadius);
// True when the transform jumps discontinuously between t0 and t1 (the simulation then carries the
// hair rigidly instead of integrating an impossible velocity).
bool headTeleportsBetween(HeadAnimation animation, double t0, double t1);
}  // namespace hp
