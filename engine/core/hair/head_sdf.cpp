#include "engine/core/hair/head_sdf.h"

#include <array>
#include <cmath>
#include <vector>

#include "engine/core/error.h"
#include "engine/core/hair/illinois_bracket.h"

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
constexpr float kGradientStep = 2e-4f;  // headGradient's central differences (m)

// The six probes of the central differences at p: +x, -x, +y, -y, +z, -z.
std::array<glm::vec3, 6> gradientProbes(const glm::vec3& p) {
  std::array<glm::vec3, 6> probes;
  for (int axis = 0; axis < 3; ++axis) {
    glm::vec3 o(0.0f);
    o[axis] = kGradientStep;
    probes[std::size_t(2 * axis)] = p + o, probes[std::size_t(2 * axis + 1)] = p - o;
  }
  return probes;
}

glm::vec3 gradientOfProbes(const float* f) {
  return glm::vec3(f[0] - f[1], f[2] - f[3], f[4] - f[5]) / (2.0f * kGradientStep);
}
}  // namespace

glm::vec3 headGradient(const glm::vec3& p) {
  const std::array<glm::vec3, 6> probes = gradientProbes(p);
  float f[6];
  for (std::size_t i = 0; i < 6; ++i) f[i] = headDistance(probes[i]);
  return gradientOfProbes(f);
}

namespace {
// One ray's root, as a parameter t along it: bisection to a 5 mm bracket (a: inside, the center; b: 0.3 m
// out, past every feature), then regula falsi until |field| < 0.1 um or no float is left between the ends.
struct RayZero {
  IllinoisBracket<float> e{0.0f, 0.3f};
  float t = 0.0f;
  bool done = false;
  float falsePosition() const {
    const float x = (e.a * e.fb - e.b * e.fa) / (e.fb - e.fa);
    return x > e.a && x < e.b ? x : 0.5f * (e.a + e.b);
  }
  void update(float f) {
    if (std::abs(f) < 1e-7f || t == e.a || t == e.b) done = true;
    else e.narrow(t, f);
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
    auto mid = [](const RayZero& r) { return 0.5f * (r.e.a + r.e.b); };
    const std::vector<float> f = alongRays(dirs, rays, mid, all);
    for (std::size_t r = 0; r < rays.size(); ++r) (f[r] < 0.0f ? rays[r].e.a : rays[r].e.b) = mid(rays[r]);
  }
  const std::vector<float> fIn = alongRays(dirs, rays, [](const RayZero& r) { return r.e.a; }, all);
  const std::vector<float> fOut = alongRays(dirs, rays, [](const RayZero& r) { return r.e.b; }, all);
  for (std::size_t r = 0; r < rays.size(); ++r) rays[r].e.fa = fIn[r], rays[r].e.fb = fOut[r], rays[r].t = rays[r].e.b;
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
  for (std::size_t r = 0; r < rays.size(); ++r)  // a ray with no root in the steps: the bracket's outer end
    surfaces[r] = kCraniumCenter + (rays[r].done ? rays[r].t : rays[r].e.b) * dirs[r];
  if (gradients.empty()) return;
  std::vector<glm::vec3> probes;  // headGradient's probes, all rays in one batch
  for (const glm::vec3& s : surfaces) {
    const std::array<glm::vec3, 6> six = gradientProbes(s);
    probes.insert(probes.end(), six.begin(), six.end());
  }
  std::vector<float> f(probes.size());
  headField().evaluate(probes, f);
  for (std::size_t r = 0; r < rays.size(); ++r) gradients[r] = gradientOfProbes(&f[6 * r]);
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
