#include "engine/core/hair/model_transform.h"

#include <cmath>
#include <cstdio>

#include "engine/core/error.h"
#include "engine/core/number_text.h"

namespace hp {
namespace {
glm::vec3 rotateUp(const glm::vec3& v, UpAxis up) {
  return up == UpAxis::Z ? glm::vec3(v.x, v.z, -v.y) : v;
}
}  // namespace

glm::vec3 ModelTransform::applyToPoint(const glm::vec3& p) const {
  return rotateUp(p * scale, up) + translation;
}

glm::vec3 ModelTransform::applyToNormal(const glm::vec3& n) const { return rotateUp(n, up); }

glm::mat4 ModelTransform::matrix() const {
  glm::mat4 m(1.0f);
  m[0] = glm::vec4(applyToNormal({scale, 0.0f, 0.0f}), 0.0f);
  m[1] = glm::vec4(applyToNormal({0.0f, scale, 0.0f}), 0.0f);
  m[2] = glm::vec4(applyToNormal({0.0f, 0.0f, scale}), 0.0f);
  m[3] = glm::vec4(translation, 1.0f);
  return m;
}

void ModelTransform::validate() const {
  if (!std::isfinite(scale) || scale <= 0.0f)
    throw Error("model transform: scale must be positive, got " + numberText(scale));
  if (!std::isfinite(translation.x + translation.y + translation.z))
    throw Error("model transform: translation is not finite");
}

std::string headSpaceRule() {
  return "components must be within +-" + std::to_string(int(kMaxHeadSpaceCoordinate));
}

void checkHeadSpaceExtent(std::span<const glm::vec3> points, const std::string& source) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    const glm::vec3& p = points[i];
    if (withinHeadSpace(p)) continue;
    char coords[96];
    std::snprintf(coords, sizeof coords, "(%g, %g, %g)", p.x, p.y, p.z);
    throw Error(source + ": point " + std::to_string(i) + " lies at " + coords + " after the model's scale and "
                "translation, past " + std::to_string(int(kMaxHeadSpaceCoordinate)) + " on an axis: check the scale and translation "
                "against the model's units");
  }
}

UpAxis parseUpAxis(const std::string& text) {
  if (text == "y" || text == "Y") return UpAxis::Y;
  if (text == "z" || text == "Z") return UpAxis::Z;
  throw Error("up axis must be \"y\" or \"z\", got \"" + text + "\"");
}

const char* upAxisName(UpAxis up) { return up == UpAxis::Z ? "z" : "y"; }
}  // namespace hp
