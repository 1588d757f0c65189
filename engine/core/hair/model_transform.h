#pragma once
// Contract: how an imported model maps into head space (Y up, metres for the default scene). Models
// in the wild are often in centimetres with Z up: scale 0.01, up Z. A point goes p -> R_up (scale * p)
// + translation, where R_up is the rotation taking the model's up axis to +Y (Z up: (x, y, z) ->
// (x, z, -y), a proper rotation, so handedness and triangle winding are kept). Normals only rotate.
#include <glm/glm.hpp>

#include <span>
#include <string>

namespace hp {
enum class UpAxis { Y, Z };

struct ModelTransform {
  float scale = 1.0f;
  UpAxis up = UpAxis::Y;
  glm::vec3 translation{0.0f};

  glm::vec3 applyToPoint(const glm::vec3& p) const;
  glm::vec3 applyToNormal(const glm::vec3& n) const;
  glm::mat4 matrix() const;  // applyToPoint as a matrix
  void validate() const;  // scale finite and > 0, translation finite
  bool operator==(const ModelTransform&) const = default;
};

// How far from the origin a point may lie in head space after the transform: 10 km in metres. Past it a
// model's distances overflow single precision where they are squared (a fit, a triangulation, a collision).
inline constexpr float kMaxHeadSpaceCoordinate = 1.0e4f;

// Every coordinate of p within kMaxHeadSpaceCoordinate of 0 (false for a NaN).
inline bool withinHeadSpace(const glm::vec3& p) {
  return glm::all(glm::lessThanEqual(glm::abs(p), glm::vec3(kMaxHeadSpaceCoordinate)));
}
// What a refusal of a vector that is not says: "components must be within +-10000".
std::string headSpaceRule();

// Throws hp::Error naming `source` when a point's coordinate is not finite or past kMaxHeadSpaceCoordinate
// (the model's scale or translation is wrong for its units).
void checkHeadSpaceExtent(std::span<const glm::vec3> points, const std::string& source);

UpAxis parseUpAxis(const std::string& text);  // "y" / "z" (any case); throws hp::Error otherwise
const char* upAxisName(UpAxis up);
}  // namespace hp
