// The path-traced reference (samples/tools/reference/) against analytic cases, on the host:
//  - a Lambertian plane under the sun returns albedo / pi x E x cos(theta) exactly, and under a
//    uniform sky of radiance Le returns albedo x Le (every cosine-weighted sample carries exactly that);
//  - a fibre filling the view under a uniform white sky returns the integral of S cos(theta_i) over the
//    sphere computed by quadrature (checks that the lobe importance sampling and its density agree);
//    with the energy-conserving physical model and no absorption that integral is the white furnace, ~1;
//  - a Lambertian plane under a point light returns albedo / pi x E x (range / d)^2 x cos(theta) (the
//    shaders' falloff), and several lights (directional, spot, point) add up exactly;
//  - the image is the same for a seed whatever the thread count, and differs for another seed;
//  - shadow rays leaving fibres of a random slab of parallel (overlapping) tubes are blocked exactly when
//    the tubes as drawn are in their way (tubes the ray starts inside do not block);
//  - one fibre under the sun returns S(L, V, T) cos(theta_i) E at every pixel;
//  - white non-absorbing fibres in a dense tuft under a uniform sky, with the sky as background, return
//    the sky everywhere (the whole tracer's furnace: many bounces, roulette, fibre-to-fibre rays);
//  - an environment map of constant radiance lights as the uniform sky, and under a map linear in direction
//    the Lambertian plane returns the exact irradiance / pi (the map's next-event estimation and the escaping
//    continuations, weighted against each other, add up to the integral).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <memory>
#include <vector>

#include "engine/core/shading/environment_map.h"
#include "engine/core/shading/fibre_model.h"
#include "samples/tools/reference/path_tracer.h"
#include "samples/tools/reference/reference_scene.h"
#include "samples/tools/reference/sampling.h"

using namespace hp;

namespace {
constexpr double kPi = 3.14159265358979323846;

// A frame with no light and no sky: the caller adds what it tests.
ExportedFrame emptyFrame(std::uint32_t size, float fovDeg, glm::vec3 eye) {
  ExportedFrame f;
  f.camera = {eye, {0, 0, 0}, {0, 1, 0}, fovDeg, size, size};
  f.lights = {LightSpec{}};
  f.lights[0].intensity = 0.0f;
  f.environment = 0.0f;
  f.background = glm::vec3(0.0f);
  f.hairAlbedo = glm::vec3(1.0f);
  return f;
}

void addStrand(ExportedFrame& f, glm::vec3 a, glm::vec3 b, float thickness) {
  f.strands.strandCount += 1;
  f.strands.defaultSegments = 1;
  for (glm::vec3 p : {a, b}) {
    f.strands.points.push_back(p);
    f.strands.thickness.push_back(thickness);
    f.strands.colors.push_back(f.hairAlbedo);
  }
}

void addQuad(ExportedFrame& f, float half, float z, glm::vec3 albedo) {
  const auto base = std::uint32_t(f.headPositions.size());
  for (glm::vec2 c : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)}) {
    f.headPositions.emplace_back(half * c.x, half * c.y, z);
    f.headNormals.emplace_back(0, 0, 1);
    f.headAlbedo.push_back(albedo);
  }
  for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) f.headIndices.push_back(base + i);
}

// The plane z = 0 fills the view; a strand lies behind it, where no ray from the plane's front goes.
ExportedFrame lambertFrame() {
  ExportedFrame f = emptyFrame(8, 20.0f, {0, 0, 3});
  addQuad(f, 10.0f, 0.0f, {0.5f, 0.25f, 0.125f});
  addStrand(f, {0, 0, -5}, {1, 0, -5}, 0.01f);
  return f;
}

// One straight fibre along x through the origin, 0.1 thick, seen from 1 m with a 2 degree view: every
// camera ray hits it. A tiny triangle far away stands in for the head.
ExportedFrame fibreFrame() {
  ExportedFrame f = emptyFrame(4, 2.0f, {0, 0, 1});
  f.environment = 1.0f;
  addStrand(f, {-2, 0, 0}, {2, 0, 0}, 0.1f);
  f.headPositions = {{500, 500, 500}, {500.001f, 500, 500}, {500, 500.001f, 500}};
  f.headNormals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
  f.headAlbedo = {glm::vec3(0.5f), glm::vec3(0.5f), glm::vec3(0.5f)};
  f.headIndices = {0, 1, 2};
  return f;
}

// int S(w, V, T) cos(theta) dw over the sphere, midpoint rule in (theta, phi), dw = cos(theta) dtheta dphi.
glm::dvec3 furnaceIntegral(FibreModel model, const HairMaterial& m, glm::dvec3 V, glm::dvec3 T) {
  const int nt = 360, np = 720;
  const glm::dvec3 U = glm::normalize(V - glm::dot(V, T) * T), W = glm::cross(T, U);
  glm::dvec3 sum(0.0);
  for (int i = 0; i < nt; ++i) {
    const double th = -0.5 * kPi + (i + 0.5) * kPi / nt;
    for (int j = 0; j < np; ++j) {
      const double ph = -kPi + (j + 0.5) * 2.0 * kPi / np;
      const glm::dvec3 L = std::sin(th) * T + std::cos(th) * (std::cos(ph) * U + std::sin(ph) * W);
      sum += exactS(model, L, V, T, m) * std::cos(th) * std::cos(th);
    }
  }
  return sum * (kPi / nt) * (2.0 * kPi / np);
}
}  // namespace

TEST(ReferenceTracer, LambertPlaneUnderTheSunMatchesTheAnalyticValue) {
  ExportedFrame f = lambertFrame();
  f.lights[0].direction = glm::normalize(glm::vec3(0.3f, 0.4f, 1.0f));
  f.lights[0].intensity = 3.0f;
  const auto r = reference::traceReference(f, {4, 1, 7, 2, nullptr});
  const double cosine = glm::normalize(glm::dvec3(0.3, 0.4, 1.0)).z;
  for (std::uint32_t c = 0; c < 3; ++c) {
    const double expected = f.headAlbedo[0][c] / kPi * 3.0 * cosine;
    for (std::uint32_t y = 0; y < 8; ++y)
      for (std::uint32_t x = 0; x < 8; ++x) EXPECT_NEAR(r.radiance.at(x, y, c), expected, 1e-5 * expected);
  }
}

// The plane point a camera ray of lambertFrame() through image point (px, py) hits: the camera at z = 3
// looks down -z with +y up, so the ray reaches z = 0 at 3 x its image-plane offset.
glm::dvec3 lambertPlanePoint(const ExportedFrame& f, double px, double py) {
  const double t = std::tan(0.5 * glm::radians(double(f.camera.fovYDeg))), w = f.camera.width, h = f.camera.height;
  return {3.0 * (2.0 * px / w - 1.0) * t, 3.0 * (1.0 - 2.0 * py / h) * t, 0.0};
}

// Radiance at the plane under a point light, averaged over pixel (x, y) on a 32 x 32 grid.
double pointLitPixel(const ExportedFrame& f, const LightSpec& l, std::uint32_t x, std::uint32_t y, int c) {
  double sum = 0.0;
  for (int j = 0; j < 32; ++j)
    for (int i = 0; i < 32; ++i) {
      const glm::dvec3 p = lambertPlanePoint(f, x + (i + 0.5) / 32.0, y + (j + 0.5) / 32.0);
      const glm::dvec3 toLight = glm::dvec3(l.position) - p;
      const double d = glm::length(toLight), falloff = double(l.range) / std::max(d, 0.1 * l.range);
      sum += f.headAlbedo[0][c] / kPi * l.color[c] * l.intensity * falloff * falloff * (toLight.z / d);
    }
  return sum / (32.0 * 32.0);
}

// Direct light only (1 bounce, no sky). Stratified over 4 x 4 cells of each pixel, where the light changes
// by up to 16% across a pixel: within 2% per pixel, 0.5% over the image.
TEST(ReferenceTracer, LambertPlaneUnderAPointLightFallsOffWithTheInverseSquare) {
  ExportedFrame f = lambertFrame();
  f.lights = {LightSpec::makePoint({0.2f, 0.1f, 1.0f}, 0.5f)};
  f.lights[0].intensity = 2.0f;
  f.lights[0].color = {1.0f, 0.5f, 0.25f};
  const auto r = reference::traceReference(f, {16, 1, 7, 2, nullptr});
  double traced = 0.0, expected = 0.0;
  for (std::uint32_t y = 0; y < 8; ++y)
    for (std::uint32_t x = 0; x < 8; ++x)
      for (int c = 0; c < 3; ++c) {
        const double e = pointLitPixel(f, f.lights[0], x, y, c);
        EXPECT_NEAR(r.radiance.at(x, y, c), e, 0.02 * e) << x << ", " << y << ", channel " << c;
        traced += r.radiance.at(x, y, c);
        expected += e;
      }
  EXPECT_NEAR(traced, expected, 0.005 * expected);
}

// Each light is its own next-event estimate: the frame with three lights is the sum of the three frames
// with one (the same camera samples for a seed; no sky, one bounce, so nothing random but the pixel).
TEST(ReferenceTracer, LightsAddUp) {
  ExportedFrame f = lambertFrame();
  LightSpec sun;
  sun.direction = glm::normalize(glm::vec3(-0.3f, 0.2f, 1.0f));
  sun.intensity = 1.5f;
  const LightSpec spot = LightSpec::makeSpot({0.0f, 0.0f, 1.5f}, {0.3f, 0.0f, 0.0f}, 12.0f);  // its edge in view
  LightSpec point = LightSpec::makePoint({-0.2f, 0.3f, 0.8f}, 0.6f);
  point.shadows = false;  // the real-time frame's switch; the reference traces every light's shadow
  const std::vector<LightSpec> lights = {sun, spot, point};
  f.lights = lights;
  const auto all = reference::traceReference(f, {4, 1, 5, 2, nullptr});
  std::vector<double> sum(all.radiance.values.size(), 0.0);
  for (const LightSpec& l : lights) {
    f.lights = {l};
    const auto one = reference::traceReference(f, {4, 1, 5, 2, nullptr});
    for (std::size_t i = 0; i < sum.size(); ++i) sum[i] += one.radiance.values[i];
  }
  double lit = 0.0;
  for (std::size_t i = 0; i < sum.size(); ++i) {
    EXPECT_NEAR(all.radiance.values[i], sum[i], 1e-5 * (1.0 + sum[i])) << "value " << i;
    lit += sum[i];
  }
  EXPECT_GT(lit, 0.0);
  f.lights.clear();  // no light, no sky: black
  const auto none = reference::traceReference(f, {4, 1, 5, 2, nullptr});
  for (float v : none.radiance.values) EXPECT_EQ(v, 0.0f);
}

TEST(ReferenceTracer, LambertPlaneUnderAUniformSkyReturnsAlbedoTimesSky) {
  ExportedFrame f = lambertFrame();
  f.environment = 0.7f;
  const auto r = reference::traceReference(f, {4, 1, 7, 2, nullptr});
  for (std::uint32_t c = 0; c < 3; ++c)
    EXPECT_NEAR(r.radiance.at(3, 5, c), f.headAlbedo[0][c] * 0.7, 1e-6);
}

// An environment map of constant radiance lights like the uniform sky of that radiance: on the Lambertian
// plane the sky's estimate is exact per sample (albedo x sky), the map's (next-event estimation and escaping
// continuations, weighted against each other) agrees on average. Measured: within 0.1%.
TEST(ReferenceTracer, AUniformEnvironmentMapLightsAsTheUniformSky) {
  ExportedFrame mapped = lambertFrame();
  mapped.environmentMap = std::make_shared<EnvironmentMap>(uniformEnvironment(glm::vec3(0.6f)));
  const auto r = reference::traceReference(mapped, {64, 2, 5, 2, nullptr});
  for (std::uint32_t c = 0; c < 3; ++c) {
    double mean = 0.0;
    for (std::uint32_t y = 0; y < 8; ++y)
      for (std::uint32_t x = 0; x < 8; ++x) mean += r.radiance.at(x, y, c) / 64.0;
    EXPECT_NEAR(mean, mapped.headAlbedo[0][c] * 0.6, 0.005 * mapped.headAlbedo[0][c] * 0.6) << c;
  }
}

// Under an environment whose radiance is linear in direction, 1 + 0.6 (d . w), the Lambertian plane (normal
// +z) returns albedo x (1 + 0.4 d.z), the irradiance / pi: the escaping rays look the map up in their own
// direction. Measured (16,384 paths per channel): within 0.2%; 1% is several standard errors.
TEST(ReferenceTracer, LambertPlaneUnderALinearEnvironmentReturnsItsIrradiance) {
  ExportedFrame f = lambertFrame();
  const glm::dvec3 axis = glm::normalize(glm::dvec3(0.3, 0.5, 0.8));
  auto map = std::make_shared<EnvironmentMap>();
  map->width = 256;
  map->height = 128;
  for (std::uint32_t y = 0; y < 128; ++y)
    for (std::uint32_t x = 0; x < 256; ++x)
      map->texels.push_back(glm::vec3(1.0 + 0.6 * glm::dot(axis, map->direction((x + 0.5) / 256.0, (y + 0.5) / 128.0))));
  f.environmentMap = map;
  const auto r = reference::traceReference(f, {256, 1, 9, 2, nullptr});
  const double irradianceOverPi = 1.0 + 0.4 * axis.z;
  for (std::uint32_t c = 0; c < 3; ++c) {
    double mean = 0.0;
    for (std::uint32_t y = 0; y < 8; ++y)
      for (std::uint32_t x = 0; x < 8; ++x) mean += r.radiance.at(x, y, c) / 64.0;
    EXPECT_NEAR(mean, f.headAlbedo[0][c] * irradianceOverPi, 0.01 * f.headAlbedo[0][c] * irradianceOverPi) << c;
  }
}

// The traced fibre's mean radiance under a sky of radiance 1 against the quadrature, per channel.
void expectFurnace(const ExportedFrame& f, FibreModel model, double tolerance) {
  const auto r = reference::traceReference(f, {1024, 1, 3, 2, nullptr});
  const glm::dvec3 expected = furnaceIntegral(model, f.material, {0, 0, 1}, {1, 0, 0});
  double traced[3] = {0.0, 0.0, 0.0};
  for (std::uint32_t c = 0; c < 3; ++c) {
    for (std::uint32_t y = 0; y < 4; ++y)
      for (std::uint32_t x = 0; x < 4; ++x) traced[c] += r.radiance.at(x, y, c) / 16.0;
    EXPECT_NEAR(traced[c], expected[c], tolerance * expected[c]) << "channel " << c;
    std::cout << f.fibreModel << " channel " << c << ": traced " << traced[c] << ", quadrature " << expected[c] << "\n";
  }
  EXPECT_GT(r.hairCoverage.at(1, 2, 0), 0.999f);
}

// Measured (seed 3, 16k samples): within 1.3% per channel.
TEST(ReferenceTracer, FibreUnderAUniformSkyReturnsTheIntegralOfItsScattering) {
  ExportedFrame f = fibreFrame();
  f.fibreModel = "marschner";
  expectFurnace(f, FibreModel::Marschner, 0.03);
}

// The white furnace through the tracer: the physical model conserves energy, so a non-absorbing fibre
// under a sky of 1 returns 1 (tests/shading/physical_test.cpp checks the quadrature itself). The
// physical model's sampler (physical_sampling.h) follows S's own structure, so every sample's weight is
// the fibre's albedo: 1 here to rounding, where the lobe-shaped mixture gave 0.978 at 4096 samples.
TEST(ReferenceTracer, WhitePhysicalFibreUnderAUniformSkyReturnsOne) {
  ExportedFrame f = fibreFrame();
  f.fibreModel = "physical";
  f.material.absorption = glm::dvec3(0.0);
  const auto r = reference::traceReference(f, {256, 1, 3, 2, nullptr});
  for (std::uint32_t c = 0; c < 3; ++c) {
    double mean = 0.0;
    for (std::uint32_t y = 0; y < 4; ++y)
      for (std::uint32_t x = 0; x < 4; ++x) mean += r.radiance.at(x, y, c) / 16.0;
    std::cout << "physical, white, channel " << c << ": " << mean << "\n";
    EXPECT_NEAR(mean, 1.0, 1e-3) << "channel " << c;
  }
}

TEST(ReferenceTracer, TheImageDependsOnTheSeedAloneNotOnTheThreadCount) {
  ExportedFrame f = lambertFrame();
  f.environment = 0.5f;
  addStrand(f, {-0.3f, -0.2f, 0.2f}, {0.3f, 0.25f, 0.1f}, 0.05f);  // in view: fibre paths too
  f.lights[0].intensity = 2.0f;
  const auto one = reference::traceReference(f, {4, 4, 11, 1, nullptr});
  const auto two = reference::traceReference(f, {4, 4, 11, 2, nullptr});
  const auto other = reference::traceReference(f, {4, 4, 12, 2, nullptr});
  EXPECT_EQ(one.radiance.values, two.radiance.values);
  EXPECT_NE(one.radiance.values, other.radiance.values);
}

namespace {
// A slab of parallel fibres along x (from x = -10 to 10) at uniform random (y, z) in [0, 1]^2, overlaps
// allowed, radius r; with a head triangle far away.
ExportedFrame slabFrame(std::uint32_t count, float r, std::vector<glm::vec2>& axes) {
  ExportedFrame f = fibreFrame();
  f.strands = {};
  reference::Sampler rng(5, 0, 0);
  for (std::uint32_t i = 0; i < count; ++i) {
    axes.emplace_back(float(rng.next()), float(rng.next()));
    addStrand(f, {-10, axes.back().x, axes.back().y}, {10, axes.back().x, axes.back().y}, 2.0f * r);
  }
  return f;
}

// Whether the ray from `o` along `d` (in the (y, z) plane, x ignored: the tubes are infinite along x) enters
// the disc of radius r around `c`, and by how much it misses the disc's edge (to skip grazing rays).
bool entersDisc(glm::dvec2 o, glm::dvec2 d, glm::dvec2 c, double r, double& margin) {
  const glm::dvec2 oc = c - o;
  const double along = glm::dot(oc, d), across = std::abs(oc.x * d.y - oc.y * d.x);
  margin = std::min(std::abs(across - r), std::abs(glm::length(oc) - r));
  if (glm::length(oc) < r) return false;  // the ray starts inside: it only leaves this tube
  return along > 0.0 && across < r;
}
}  // namespace

// Rays leave a random fibre of a slab from its surface (reference::fibreExitOrigin) toward random
// directions; each is blocked exactly when it enters another tube (2D geometry in the slab's cross-section:
// the tubes are infinite along x). 12% of axis points lie inside another tube here: rays leaving from
// the axis were blocked by those tubes' insides.
TEST(ReferenceTracer, RaysLeavingFibresOfASlabAreBlockedExactlyByTheTubesInTheirWay) {
  std::vector<glm::vec2> axes;
  const float r = 0.02f;
  const ExportedFrame f = slabFrame(100, r, axes);
  const reference::ReferenceScene scene(f);
  reference::Sampler rng(9, 0, 0);
  std::uint32_t checked = 0, escaped = 0, mismatched = 0, offSurface = 0;
  for (std::uint32_t i = 0; i < 20000; ++i) {
    const auto from = std::min(std::uint32_t(rng.next() * axes.size()), std::uint32_t(axes.size() - 1));
    const double phi = 2.0 * kPi * rng.next(), tilt = (rng.next() - 0.5) * 2.0;  // up to ~57 degrees off the plane
    const glm::dvec3 dir = glm::normalize(glm::dvec3(std::tan(tilt), std::cos(phi), std::sin(phi)));
    reference::SceneHit h;
    h.kind = reference::SceneHit::Kind::Fibre;
    h.strand = from;
    h.tangent = {1, 0, 0};
    h.radius = r;
    h.axisPoint = {0.0, axes[from].x, axes[from].y};
    const glm::dvec3 o = reference::fibreExitOrigin(h, dir);
    const glm::dvec3 side = o - h.axisPoint;  // on the tube (x unchanged), on the side the ray goes to
    offSurface += (std::abs(glm::length(side) - r) > 0.01 * r || side.x != 0.0 || glm::dot(side, dir) < 0.0) ? 1u : 0u;
    const glm::dvec2 o2(o.y, o.z), d2 = glm::normalize(glm::dvec2(dir.y, dir.z));
    bool expected = false;
    double nearest = 1.0;
    for (std::size_t j = 0; j < axes.size(); ++j) {
      if (j == from) continue;  // its own tube: the ray leaves it
      double margin = 0.0;
      expected = entersDisc(o2, d2, glm::dvec2(axes[j]), r, margin) || expected;
      nearest = std::min(nearest, margin);
    }
    if (nearest < 1e-2 * r) continue;  // grazing: Embree's round curves are exact to ~1e-3 of the radius
    ++checked;
    escaped += expected ? 0u : 1u;
    const bool blocked = scene.occluded(o, dir, 0.0f, std::numeric_limits<float>::infinity());
    const reference::SceneHit first = scene.intersect(o, dir, 0.0f);
    mismatched += (blocked != expected || (first.kind == reference::SceneHit::Kind::Fibre) != expected) ? 1u : 0u;
  }
  std::cout << checked << " rays checked, " << escaped << " escaped, " << mismatched << " disagree with the tubes\n";
  EXPECT_EQ(offSurface, 0u);
  EXPECT_GT(checked, 18000u);
  EXPECT_GT(escaped, checked / 10);
  EXPECT_LT(escaped, checked * 9 / 10);
  EXPECT_EQ(mismatched, 0u);
}

// The mean of the 4x4 image of fibreFrame()'s fibre (physical) against S(L, V, T) cos(theta_i) E for a sun of
// irradiance 2 along L, V = (0, 0, 1): within 1% per channel.
void expectTheSunsImage(const reference::TraceResult& r, const ExportedFrame& f, const glm::dvec3& L, const char* what) {
  const glm::dvec3 V(0, 0, 1), T(1, 0, 0);
  const double cosTheta = std::sqrt(1.0 - glm::dot(L, T) * glm::dot(L, T));
  const glm::dvec3 expected = exactS(FibreModel::Physical, L, V, T, f.material) * cosTheta * 2.0;
  for (std::uint32_t c = 0; c < 3; ++c) {
    double mean = 0.0;
    for (std::uint32_t y = 0; y < 4; ++y)
      for (std::uint32_t x = 0; x < 4; ++x) mean += r.radiance.at(x, y, c) / 16.0;
    std::cout << "channel " << c << ": traced " << what << " " << mean << ", S cos E " << expected[c] << "\n";
    EXPECT_NEAR(mean, expected[c], 0.01 * expected[c]) << "channel " << c;
  }
}

// One fibre along x under the sun, seen along -z: every camera ray hits it and is lit (its own tube does
// not shadow the side facing the light), so each pixel is S(L, V, T) cos(theta_i) E for its view ray.
// The view is 2 degrees wide: V is (0, 0, 1) within 1 degree.
TEST(ReferenceTracer, OneFibreUnderTheSunReturnsItsScatteringFunction) {
  ExportedFrame f = fibreFrame();
  f.environment = 0.0f;
  f.fibreModel = "physical";
  f.lights[0].direction = glm::normalize(glm::vec3(0.3f, 0.5f, 0.8f));
  f.lights[0].intensity = 2.0f;
  const auto r = reference::traceReference(f, {16, 1, 3, 2, nullptr});
  expectTheSunsImage(r, f, glm::dvec3(f.lights[0].direction), "under the sun");
}

// The same fibre under an environment map that is black but for a small disc around the sun's direction
// (radius 0.75 degrees, its texels' radiance chosen so they deliver the same irradiance): the map's next-event
// estimation finds the disc that the fibre's own sampling almost never hits, and the image is the sun's within
// what the disc's width changes. Measured: 0.3-0.4% low per channel (a 1.5-degree disc read 1.4% high: S
// curves across it).
TEST(ReferenceTracer, OneFibreUnderASmallBrightDiscReturnsTheSunsImage) {
  ExportedFrame f = fibreFrame();
  f.environment = 0.0f;
  f.fibreModel = "physical";
  const glm::dvec3 L = glm::normalize(glm::dvec3(0.3, 0.5, 0.8));
  const double cosRadius = std::cos(glm::radians(0.75));
  auto map = std::make_shared<EnvironmentMap>();
  map->width = 2048;
  map->height = 1024;
  double discSolidAngle = 0.0;  // of the texels inside, so that the map delivers exactly 2
  for (std::uint32_t y = 0; y < map->height; ++y)
    for (std::uint32_t x = 0; x < map->width; ++x) {
      const bool inside = glm::dot(map->texelDirection(x, y), L) > cosRadius;
      map->texels.push_back(glm::vec3(inside ? 1.0f : 0.0f));
      discSolidAngle += inside ? map->texelSolidAngle(y) : 0.0;
    }
  map->intensity = 2.0 / discSolidAngle;
  f.environmentMap = map;
  f.lights.clear();
  const auto r = reference::traceReference(f, {256, 1, 3, 2, nullptr});
  expectTheSunsImage(r, f, L, "under the disc");
}

// The whole tracer's white furnace: 400 white non-absorbing fibres of the physical model crossing a
// 0.2 m box at random, under a uniform sky of 1 with a background of 1: light is neither made nor lost,
// so every pixel returns 1 up to noise, however many bounces a path takes between fibres (far more are
// allowed than paths need; roulette ends them). It holds the fibre sampler's density and the roulette to
// account over many bounces (the lobe-mixture sampler read 0.56 and 2.05 at 4k and 65k paths); every white
// bounce weighs 1 whatever the geometry, so where rays go is the slab test's to check. Seeds 3-11 read
// 0.987-1.011 (this one, seed 3, the farthest); the 2% bound is past that spread.
TEST(ReferenceTracer, WhiteFibresInADenseTuftUnderAUniformSkyReturnTheSky) {
  ExportedFrame f = fibreFrame();
  f.strands = {};
  f.fibreModel = "physical";
  f.material.absorption = glm::dvec3(0.0);
  f.environment = 1.0f;
  f.background = glm::vec3(1.0f);
  f.camera = {{0, 0, 1}, {0, 0, 0}, {0, 1, 0}, 8.0f, 8, 8};
  reference::Sampler rng(4, 0, 0);
  const auto point = [&] { return glm::vec3(rng.next() - 0.5, rng.next() - 0.5, rng.next() - 0.5) * 0.2f; };
  for (int i = 0; i < 400; ++i) {
    const glm::vec3 c = point(), d = glm::normalize(point());
    addStrand(f, c - 0.3f * d, c + 0.3f * d, 0.004f);
  }
  const auto r = reference::traceReference(f, {64, 1000, 3, 2, nullptr});
  double mean = 0.0, coverage = 0.0;
  for (std::uint32_t y = 0; y < 8; ++y)
    for (std::uint32_t x = 0; x < 8; ++x) {
      mean += r.radiance.at(x, y, 1) / 64.0;
      coverage += r.hairCoverage.at(x, y, 0) / 64.0;
    }
  std::cout << "white tuft under a sky of 1: mean " << mean << ", hair coverage " << coverage << "\n";
  EXPECT_GT(coverage, 0.5);
  EXPECT_NEAR(mean, 1.0, 0.02);
}
