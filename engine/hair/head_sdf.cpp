#include "engine/hair/head_sdf.h"

#include <cmath>
#include <vector>

#include "engine/error.h"

namespace hp {
namespace {
using glm::vec3;

// Cranium, brow, face, cheekbones (mirrored: one leaf per left/right pair), jaw, chin.
void skull(sdf::Program& f) {
  f.ellipsoid(kCraniumCenter, {0.074f, 0.088f, 0.097f});
  f.capsule({0.0f, 0.021f, 0.080f}, {0.038f, 0.021f, 0.076f}, 0.012f, true).smoothUnion(0.02f);  // brow
  f.ellipsoid({0.0f, -0.050f, 0.022f}, {0.061f, 0.065f, 0.066f}).smoothUnion(0.03f);              // face
  f.ellipsoid({0.044f, -0.026f, 0.058f}, {0.022f, 0.016f, 0.024f}, true).smoothUnion(0.02f);      // cheekbone
  f.capsule({0.047f, -0.045f, -0.005f}, {0.020f, -0.108f, 0.052f}, 0.018f, true).smoothUnion(0.03f);  // jaw
  f.ellipsoid({0.0f, -0.112f, 0.068f}, {0.024f, 0.019f, 0.020f}).smoothUnion(0.015f);             // chin
}

void features(sdf::Program& f) {
  f.sphere({0.031f, -0.001f, 0.091f}, 0.018f, true).smoothSubtract(0.008f);                       // eye socket
  f.sphere({0.031f, 0.000f, 0.066f}, 0.0125f, true).smoothUnion(0.003f);                          // eye
  f.taperedCapsule({0.0f, 0.004f, 0.088f}, {0.0f, -0.038f, 0.113f}, 0.007f, 0.010f).smoothUnion(0.008f);  // nose
  f.ellipsoid({0.0f, -0.043f, 0.102f}, {0.019f, 0.010f, 0.011f}).smoothUnion(0.014f);             // nostrils
  f.ellipsoid({0.0f, -0.070f, 0.087f}, {0.024f, 0.008f, 0.010f}).smoothUnion(0.006f);             // upper lip
  f.ellipsoid({0.0f, -0.084f, 0.083f}, {0.021f, 0.008f, 0.010f}).smoothUnion(0.006f);             // lower lip
  f.ellipsoid({0.074f, -0.018f, -0.012f}, {0.011f, 0.031f, 0.019f}, true).smoothUnion(0.006f);    // ear
}

// Neck, shoulders and chest, cut flat below the chest.
void body(sdf::Program& f) {
  f.taperedCapsule({0.0f, -0.06f, -0.022f}, {0.0f, -0.25f, -0.020f}, 0.050f, 0.057f);             // neck
  f.capsule({0.0f, -0.275f, -0.02f}, {0.165f, -0.268f, -0.02f}, 0.052f, true);                   // shoulders
  f.ellipsoid({0.0f, -0.36f, -0.015f}, {0.185f, 0.11f, 0.105f}).smoothUnion(0.06f);              // chest
  f.smoothUnion(0.07f).belowPlaneY(kHeadFieldLow.y + 0.03f).max();
}

sdf::Program buildHead() {
  sdf::Program f;
  skull(f);
  features(f);
  body(f);
  return f.smoothUnion(0.025f);
}
}  // namespace

const sdf::Program& headField() {
  static const sdf::Program f = buildHead();
  return f;
}

float headDistance(const glm::vec3& p) { return headField()(p); }

namespace {
template <typename F>
glm::vec3 centralDifference(const F& f, const glm::vec3& p) {
  const float h = 2e-4f;
  return glm::vec3(f(p + vec3(h, 0, 0)) - f(p - vec3(h, 0, 0)), f(p + vec3(0, h, 0)) - f(p - vec3(0, h, 0)),
                   f(p + vec3(0, 0, h)) - f(p - vec3(0, 0, h))) /
         (2.0f * h);
}
}  // namespace

glm::vec3 headGradient(const glm::vec3& p) { return centralDifference(headDistance, p); }

namespace {
// One ray's root: bisection to a 5 mm bracket, then regula falsi (Illinois: an end kept twice has its
// value halved) until |field| < 0.1 um or no float is left between the ends.
struct RayZero {
  float inside = 0.0f, outside = 0.3f;  // the center is inside, 0.3 m out is past every feature
  float fIn = 0.0f, fOut = 0.0f, t = 0.0f;
  int kept = 0;
  bool done = false;
  float falsePosition() const {
    const float x = (inside * fOut - outside * fIn) / (fOut - fIn);
    return x > inside && x < outside ? x : 0.5f * (inside + outside);
  }
  void update(float f) {
    if (std::abs(f) < 1e-7f || t == inside || t == outside) {
      done = true;
    } else if (f < 0.0f) {
      inside = t, fIn = f, kept = kept < 0 ? kept - 1 : -1;
      if (kept <= -2) fOut *= 0.5f;
    } else {
      outside = t, fOut = f, kept = kept > 0 ? kept + 1 : 1;
      if (kept >= 2) fIn *= 0.5f;
    }
  }
};

// The field at kCraniumCenter + t(ray) dir for every ray `pick` selects, in one batch.
template <typename T, typename Pick>
std::vector<float> alongRays(std::span<const glm::vec3> dirs, std::span<RayZero> rays, T t, Pick pick) {
  std::vector<glm::vec3> points;
  for (std::size_t i = 0; i < rays.size(); ++i)
    if (pick(rays[i])) points.push_back(kCraniumCenter + t(rays[i]) * dirs[i]);
  std::vector<float> values(points.size());
  headField().evaluate(points, values);
  return values;
}
}  // namespace

void headSurfacesAlong(std::span<const glm::vec3> dirs, std::span<glm::vec3> surfaces, std::span<glm::vec3> gradients) {
  if (surfaces.size() != dirs.size() || (!gradients.empty() && gradients.size() != dirs.size()))
    throw Error("head surface: one surface point (and gradient, if any) per ray");
  std::vector<RayZero> rays(dirs.size());
  auto all = [](const RayZero&) { return true; };
  for (int i = 0; i < 6; ++i) {
    auto mid = [](const RayZero& r) { return 0.5f * (r.inside + r.outside); };
    const std::vector<float> f = alongRays(dirs, rays, mid, all);
    for (std::size_t r = 0; r < rays.size(); ++r) (f[r] < 0.0f ? rays[r].inside : rays[r].outside) = mid(rays[r]);
  }
  const std::vector<float> fIn = alongRays(dirs, rays, [](const RayZero& r) { return r.inside; }, all);
  const std::vector<float> fOut = alongRays(dirs, rays, [](const RayZero& r) { return r.outside; }, all);
  for (std::size_t r = 0; r < rays.size(); ++r) rays[r].fIn = fIn[r], rays[r].fOut = fOut[r], rays[r].t = rays[r].outside;
  auto active = [](const RayZero& r) { return !r.done; };
  for (int step = 0; step < 24; ++step) {
    for (RayZero& r : rays)
      if (!r.done) r.t = r.falsePosition();
    const std::vector<float> f = alongRays(dirs, rays, [](const RayZero& r) { return r.t; }, active);
    if (f.empty()) break;
    std::size_t k = 0;
    for (RayZero& r : rays)
      if (!r.done) r.update(f[k++]);
  }
  for (RayZero& r : rays)
    if (!r.done) r.t = r.outside;  // no root found in the steps: the bracket's outer end
  // Gradients: headGradient's six probes per point, one batch.
  constexpr float h = 2e-4f;
  std::vector<glm::vec3> probes;
  for (std::size_t r = 0; r < rays.size(); ++r) {
    surfaces[r] = kCraniumCenter + rays[r].t * dirs[r];
    for (int axis = 0; axis < 3; ++axis) {
      glm::vec3 o(0.0f);
      o[axis] = h;
      probes.push_back(surfaces[r] + o), probes.push_back(surfaces[r] - o);
    }
  }
  std::vector<float> f(probes.size());
  headField().evaluate(probes, f);
  for (std::size_t r = 0; r < rays.size() && !gradients.empty(); ++r)
    gradients[r] = glm::vec3(f[6 * r] - f[6 * r + 1], f[6 * r + 2] - f[6 * r + 3], f[6 * r + 4] - f[6 * r + 5]) / (2.0f * h);
}

glm::vec3 headSurfaceAlong(const glm::vec3& dir, glm::vec3* gradient) {
  glm::vec3 surface, g;
  headSurfacesAlong({&dir, 1}, {&surface, 1}, {&g, 1});
  if (gradient) *gradient = g;
  return surface;
}

bool aboveHairline(const glm::vec3& dir) {
  const float azimuth = std::atan2(dir.x, dir.z);  // 0 at the face, +-pi at the back
  // Height of the hairline: 0.55 at the forehead, 0.25 above the ears, -0.45 at the nape.
  const float line = 0.15f + 0.5f * std::cos(azimuth) - 0.1f * std::cos(2.0f * azimuth);
  return dir.y > line;
}

bool inFaceRegion(const glm::vec3& s) {
  return s.z > 0.02f && s.y < 0.035f && s.y > -0.13f && std::abs(s.x) < 0.062f;
}
}  // namespace hp
