#include "tests/render/head_light_reference.h"

#include <cmath>
#include <optional>

#include "compute/raster/camera.h"

namespace hp::test {
namespace {
constexpr int kMaxSteps = 400;

// First t in [t0, tMax] where the grid's distance drops below `hitEpsilon`.
std::optional<float> sphereTrace(const SdfGrid& sdf, glm::vec3 origin, glm::vec3 dir, float t0, float tMax) {
  const float hitEpsilon = 0.05f * sdf.cell;
  float t = t0;
  for (int i = 0; i < kMaxSteps && t < tMax; ++i) {
    const float d = sdf.sample(origin + t * dir);
    if (d < hitEpsilon) return t;
    t += std::max(d, 0.025f * sdf.cell);
  }
  return std::nullopt;
}

// Whether the shadow ray from surface point p keeps clear of the head: at every t its distance to the
// surface is at least min(margin, t * cosine / 2), i.e. half of what a flat surface alone would give
// near p, and the full margin further out (a blocked ray fails at once).
bool rayKeepsClear(const SdfGrid& sdf, glm::vec3 p, glm::vec3 dir, float cosine, float margin, float tMax) {
  float t = sdf.cell;
  for (int i = 0; i < kMaxSteps && t < tMax; ++i) {
    const float d = sdf.sample(p + t * dir);
    if (d < std::min(margin, 0.5f * cosine * t)) return false;
    t += std::max(0.5f * d, 0.1f * sdf.cell);  // half steps: a near miss is not stepped over
  }
  return true;
}

// Where the ray from surface point p along dir (into the body: p faces away from dir) leaves the body again:
// the first point past the inside (distance < 0) where the distance is positive again. nullopt where it does
// not enter the body within 3 cells (a grazing ray: its own body is not what it crosses first) or never leaves
// within tMax. Half steps inside, as rayKeepsClear takes outside.
std::optional<glm::vec3> exitPoint(const SdfGrid& sdf, glm::vec3 p, glm::vec3 dir, float tMax) {
  bool inside = false;
  float t = 0.1f * sdf.cell;
  for (int i = 0; i < 8 * kMaxSteps && t < tMax; ++i) {
    const float d = sdf.sample(p + t * dir);
    inside |= d < 0.0f;
    if (!inside && t > 3.0f * sdf.cell) return std::nullopt;
    if (inside && d > 0.05f * sdf.cell) return p + t * dir;
    t += std::max(0.5f * std::abs(d), 0.1f * sdf.cell);
  }
  return std::nullopt;
}
}  // namespace

HeadLightMap traceHeadLight(const SdfGrid& head, const CameraSpec& camera, const LightSpec& light,
                            std::uint32_t width, std::uint32_t height, const HeadLightOptions& options) {
  const float aspect = float(width) / float(height);
  const CameraMatrices m = orbitCamera(camera, aspect);
  const glm::mat3 viewToWorld = glm::transpose(glm::mat3(m.view));
  const float tanHalf = std::tan(0.5f * m.fovY);
  const float extent = glm::length(head.upper() - head.origin);
  const float far = glm::length(m.position - 0.5f * (head.origin + head.upper())) + extent;
  const glm::vec3 toLight = glm::normalize(light.direction);

  HeadLightMap out{width, height, std::vector<bool>(std::size_t(width) * height),
                   std::vector<bool>(std::size_t(width) * height)};
  for (std::uint32_t y = 0; y < height; ++y)
    for (std::uint32_t x = 0; x < width; ++x) {
      const float sx = (2.0f * (float(x) + 0.5f) / float(width) - 1.0f) * tanHalf * aspect;
      const float sy = (1.0f - 2.0f * (float(y) + 0.5f) / float(height)) * tanHalf;  // rows top to bottom
      const glm::vec3 dir = glm::normalize(viewToWorld * glm::vec3(sx, sy, -1.0f));
      const std::optional<float> t = sphereTrace(head, m.position, dir, 0.0f, far);
      if (!t) continue;
      const std::size_t pixel = std::size_t(y) * width + x;
      out.hit[pixel] = true;
      const glm::vec3 p = m.position + *t * dir;
      const glm::vec3 n = glm::normalize(head.gradient(p));
      if (glm::dot(n, toLight) < options.minCosine) continue;
      const float cosine = glm::dot(n, toLight);
      if (cosine < 0.0f && options.pastOwnBody) {
        const std::optional<glm::vec3> exit = exitPoint(head, p, toLight, extent);
        // From where it leaves the body the ray keeps clear as from a surface facing the light head-on.
        out.clearLit[pixel] = exit && rayKeepsClear(head, *exit, toLight, 1.0f, options.margin, extent);
        continue;
      }
      out.clearLit[pixel] = rayKeepsClear(head, p, toLight, cosine, options.margin, extent);
    }
  return out;
}
}  // namespace hp::test
