#include "engine/hair/head_sdf.h"

#include <cmath>

#include "engine/hair/sdf_primitives.h"

namespace hp {
namespace {
using glm::vec3;

// Mirror in x so left and right features are one primitive each.
vec3 mirrored(const vec3& p) { return {std::abs(p.x), p.y, p.z}; }

float skull(const vec3& p) {
  const vec3 m = mirrored(p);
  float d = sdf::ellipsoid(p, kCraniumCenter, {0.074f, 0.088f, 0.097f});
  d = sdf::smoothUnion(d, sdf::capsule(m, {0.0f, 0.021f, 0.080f}, {0.038f, 0.021f, 0.076f}, 0.012f), 0.02f);  // brow
  d = sdf::smoothUnion(d, sdf::ellipsoid(p, {0.0f, -0.050f, 0.022f}, {0.061f, 0.065f, 0.066f}), 0.03f);        // face
  d = sdf::smoothUnion(d, sdf::ellipsoid(m, {0.044f, -0.026f, 0.058f}, {0.022f, 0.016f, 0.024f}), 0.02f);      // cheekbone
  d = sdf::smoothUnion(d, sdf::capsule(m, {0.047f, -0.045f, -0.005f}, {0.020f, -0.108f, 0.052f}, 0.018f), 0.03f);  // jaw
  d = sdf::smoothUnion(d, sdf::ellipsoid(p, {0.0f, -0.112f, 0.068f}, {0.024f, 0.019f, 0.020f}), 0.015f);       // chin
  return d;
}

float features(const vec3& p, float d) {
  const vec3 m = mirrored(p);
  d = sdf::smoothSubtract(d, sdf::sphere(m, {0.031f, -0.001f, 0.091f}, 0.018f), 0.008f);                    // eye socket
  d = sdf::smoothUnion(d, sdf::sphere(m, {0.031f, 0.000f, 0.066f}, 0.0125f), 0.003f);                       // eye
  d = sdf::smoothUnion(d, sdf::taperedCapsule(p, {0.0f, 0.004f, 0.088f}, {0.0f, -0.038f, 0.113f}, 0.007f, 0.010f), 0.008f);  // nose
  d = sdf::smoothUnion(d, sdf::ellipsoid(p, {0.0f, -0.043f, 0.102f}, {0.019f, 0.010f, 0.011f}), 0.014f);   // nostrils
  d = sdf::smoothUnion(d, sdf::ellipsoid(p, {0.0f, -0.070f, 0.087f}, {0.024f, 0.008f, 0.010f}), 0.006f);   // upper lip
  d = sdf::smoothUnion(d, sdf::ellipsoid(p, {0.0f, -0.084f, 0.083f}, {0.021f, 0.008f, 0.010f}), 0.006f);   // lower lip
  const float ear = sdf::ellipsoid(m, {0.074f, -0.018f, -0.012f}, {0.011f, 0.031f, 0.019f});
  return sdf::smoothUnion(d, ear, 0.006f);
}

float body(const vec3& p) {
  const vec3 m = mirrored(p);
  float neck = sdf::taperedCapsule(p, {0.0f, -0.06f, -0.022f}, {0.0f, -0.25f, -0.020f}, 0.050f, 0.057f);
  float shoulders = sdf::capsule(m, {0.0f, -0.275f, -0.02f}, {0.165f, -0.268f, -0.02f}, 0.052f);
  float chest = sdf::ellipsoid(p, {0.0f, -0.36f, -0.015f}, {0.185f, 0.11f, 0.105f});
  float d = sdf::smoothUnion(neck, sdf::smoothUnion(shoulders, chest, 0.06f), 0.07f);
  return std::max(d, kHeadFieldLow.y + 0.03f - p.y);  // cut flat below the chest
}
}  // namespace

float headDistance(const glm::vec3& p) { return sdf::smoothUnion(features(p, skull(p)), body(p), 0.025f); }

glm::vec3 headGradient(const glm::vec3& p) {
  const float h = 2e-4f;
  return glm::vec3(headDistance(p + vec3(h, 0, 0)) - headDistance(p - vec3(h, 0, 0)),
                   headDistance(p + vec3(0, h, 0)) - headDistance(p - vec3(0, h, 0)),
                   headDistance(p + vec3(0, 0, h)) - headDistance(p - vec3(0, 0, h))) /
         (2.0f * h);
}

glm::vec3 headSurfaceAlong(const glm::vec3& dir) {
  float inside = 0.0f, outside = 0.3f;  // the center is inside, 0.3 m out is past every feature
  for (int i = 0; i < 40; ++i) {
    const float mid = 0.5f * (inside + outside);
    (headDistance(kCraniumCenter + mid * dir) < 0.0f ? inside : outside) = mid;
  }
  return kCraniumCenter + outside * dir;
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
