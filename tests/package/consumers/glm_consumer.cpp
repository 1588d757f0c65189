// An application whose glm is configured left-handed (GLM_FORCE_LEFT_HANDED, set by its build): its own
// glm::lookAt / glm::perspective stay left-handed, and hairpipe's views stay right-handed with [0, 1] depth,
// in one program. Were hairpipe to force glm macros, or to share instantiations of glm's macro-dependent
// templates with the application, one of the two checks below would fail.
#include <cmath>
#include <cstdio>

#include <glm/gtc/matrix_transform.hpp>

#include <hairpipe/hairpipe.h>

int main() {
  int failures = 0;
  // The application's own camera: left-handed, so a point in front of the eye has view-space z > 0.
  const glm::mat4 own = glm::lookAt(glm::vec3(0, 0, -2), glm::vec3(0, 0, 0), glm::vec3(0, 1, 0));
  const glm::vec4 ownPoint = own * glm::vec4(0, 0, 0, 1);
  const glm::mat4 ownProj = glm::perspective(0.8f, 1.0f, 1.0f, 10.0f);
  const glm::vec4 ownNear = ownProj * glm::vec4(0, 0, 1, 1);  // on the near plane, in front (+z)
  if (!(ownPoint.z > 0.0f) || std::fabs(ownNear.z / ownNear.w + 1.0f) > 1e-4f) {  // glm's default depth: [-1, 1]
    std::printf("FAILED: the application's glm is not left-handed with [-1, 1] depth (z %.3f, near depth %.3f)\n",
                ownPoint.z, ownNear.z / ownNear.w);
    ++failures;
  }
  // hairpipe's view of the same scene: right-handed (in front: view-space z < 0), depth 0 at the near plane.
  const hairpipe::Result<hairpipe::View> view =
      hairpipe::makeView({{0, 0, 2}, {0, 0, 0}, {0, 1, 0}, 0.8f, 1.0f, 10.0f}, {64, 64});
  if (!view) return std::printf("FAILED: %s\n", view.message().c_str()), 1;
  const float* v = view->view.m;
  const float* p = view->projection.m;
  const float z = v[2] * 0 + v[6] * 0 + v[10] * 0 + v[14];               // the origin in view space
  const float clipZ = p[10] * -1.0f + p[14], clipW = p[11] * -1.0f + p[15];  // a point at view z = -near
  if (!(z < 0.0f) || std::fabs(clipZ / clipW) > 1e-5f) {
    std::printf("FAILED: hairpipe's view is not right-handed with [0, 1] depth (z %.3f, near depth %.5f)\n", z, clipZ / clipW);
    ++failures;
  }
  if (failures == 0) std::printf("ok: the application's glm is left-handed [-1, 1], hairpipe's views right-handed [0, 1]\n");
  return failures;
}
