// The environment light on the host (engine/core/shading/environment_map.h, environment_sh.h, furnace.h):
//  - an equirectangular map looks up its texel centres exactly, wraps in azimuth and turns with its rotation;
//  - the SH projection of a uniform map is the uniform SH, and of a radiance linear in direction, a + b (d . w),
//    gives after the cosine convolution the exact irradiance / pi, a + (2/3) b (d . n);
//  - the studio environment's irradiance from its SH stays close to a brute-force cosine integral of the map
//    (the order-2 truncation's error, measured);
//  - the sky albedo's parts from the viewer's side and from behind add up to the whole.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <iostream>
#include <random>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "engine/core/error.h"
#include "engine/core/shading/environment_lights.h"
#include "engine/core/shading/environment_map.h"
#include "engine/core/shading/environment_sh.h"
#include "engine/core/shading/furnace.h"
#include "engine/core/shading/material.h"
#include "tests/shading/random_directions.h"

using namespace hp;

namespace {
constexpr double kPiValue = 3.14159265358979323846;

EnvironmentMap mapOf(std::uint32_t w, std::uint32_t h, const std::function<glm::dvec3(glm::dvec3)>& radiance) {
  return sampledEnvironment(w, h, [&](const glm::dvec3& d) { return radiance(d); });
}

std::vector<glm::dvec3> unitVectors(int count, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<glm::dvec3> out;
  for (int i = 0; i < count; ++i) out.push_back(test::uniformUnit(rng));
  return out;
}

// Irradiance / pi at normal n by summing the map's texels (each its solid angle) times the clamped cosine.
glm::dvec3 bruteForceIrradianceOverPi(const EnvironmentMap& map, const glm::dvec3& n) {
  glm::dvec3 sum(0.0);
  for (std::uint32_t y = 0; y < map.height; ++y) {
    const double omega = (std::cos(kPiValue * y / map.height) - std::cos(kPiValue * (y + 1) / map.height)) * 2.0 *
                         kPiValue / map.width;
    for (std::uint32_t x = 0; x < map.width; ++x) {
      const glm::dvec3 d = map.direction((x + 0.5) / map.width, (y + 0.5) / map.height);
      sum += glm::dvec3(map.texels[std::size_t(y) * map.width + x]) * (std::max(glm::dot(d, n), 0.0) * omega);
    }
  }
  return sum * map.intensity / kPiValue;
}
}  // namespace

TEST(EnvironmentMap, LooksUpTexelCentresWrapsAndTurns) {
  const EnvironmentMap map = mapOf(64, 32, [](glm::dvec3 d) { return glm::dvec3(1.0 + d.x, 1.0 + d.y, 1.0 + d.z); });
  for (std::uint32_t y = 0; y < 32; y += 5)
    for (std::uint32_t x = 0; x < 64; x += 7) {
      const glm::dvec3 d = map.direction((x + 0.5) / 64.0, (y + 0.5) / 32.0);
      const glm::dvec3 got = map.radiance(d);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], 1.0 + d[c], 1e-5) << x << "," << y;
    }
  // Straight behind (-z) is the seam between the last column and the first: both sides blend the same two.
  EXPECT_NEAR(map.radiance({1e-9, 0.0, -1.0}).z, map.radiance({-1e-9, 0.0, -1.0}).z, 1e-6);
  EnvironmentMap turned = map;
  turned.rotationDeg = 90.0;
  turned.intensity = 2.0;
  // Turned a quarter counter-clockwise seen from above, what came from +z comes from +x.
  const glm::dvec3 fromX = turned.radiance({1.0, 0.0, 0.0}), fromZ = map.radiance({0.0, 0.0, 1.0});
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(fromX[c], 2.0 * fromZ[c], 1e-3);
}

TEST(EnvironmentMap, RefusesBadMapsByName) {
  EnvironmentMap map = uniformEnvironment(glm::vec3(1.0f));
  map.texels[0].y = std::nanf("");
  EXPECT_THROW(map.validate(), Error);
  map = uniformEnvironment(glm::vec3(-1.0f));
  EXPECT_THROW(map.validate(), Error);
  map = uniformEnvironment(glm::vec3(1.0f));
  map.intensity = -1.0;
  EXPECT_THROW(map.validate(), Error);
  map.intensity = 1.0;
  map.width = 2;
  try {
    map.validate();
    FAIL() << "a map with fewer texels than its size passed";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("number of texels"), std::string::npos) << e.what();
  }
}

TEST(EnvironmentSH, UniformMapProjectsToTheUniformCoefficients) {
  const EnvironmentSH sh = projectEnvironment(mapOf(128, 64, [](glm::dvec3) { return glm::dvec3(0.3, 0.5, 0.7); }));
  const EnvironmentSH expected = uniformEnvironmentSH({0.3, 0.5, 0.7});
  for (std::size_t i = 0; i < sh.size(); ++i)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(sh[i][c], expected[i][c], 1e-3) << "coefficient " << i;  // 5e-4 seen
  const EnvironmentSH convolved = cosineConvolved(sh);
  for (const glm::dvec3& n : unitVectors(20, 5))
    EXPECT_NEAR(evaluateEnvironment(convolved, n).y, 0.5, 1e-4);
}

TEST(EnvironmentSH, LinearRadianceGivesTheExactIrradiance) {
  const glm::dvec3 axis = glm::normalize(glm::dvec3(0.3, 0.8, -0.5));
  const EnvironmentMap map = mapOf(256, 128, [&](glm::dvec3 w) { return glm::dvec3(1.0 + 0.6 * glm::dot(axis, w)); });
  const EnvironmentSH convolved = cosineConvolved(projectEnvironment(map));
  for (const glm::dvec3& n : unitVectors(50, 11)) {
    const double expected = 1.0 + (2.0 / 3.0) * 0.6 * glm::dot(axis, n);
    EXPECT_NEAR(evaluateEnvironment(convolved, n).x, expected, 2e-4);
    EXPECT_NEAR(bruteForceIrradianceOverPi(map, n).x, expected, 2e-4);
  }
}

// Measured: over 200 normals the whole studio's order-2 irradiance differs from the brute-force integral by
// at most 9.3% of the brute force's mean (RMS 4.2%): its lights are too small for 9 coefficients, which is
// why splitEnvironment draws them as lights.
TEST(EnvironmentSH, StudioIrradianceFromNineCoefficientsStaysNearTheIntegral) {
  const EnvironmentMap studio = studioEnvironment(128, 64);
  const EnvironmentSH convolved = cosineConvolved(projectEnvironment(studio));
  double worst = 0.0, squares = 0.0, mean = 0.0;
  const auto normals = unitVectors(200, 3);
  std::vector<double> exact;
  for (const glm::dvec3& n : normals) exact.push_back(bruteForceIrradianceOverPi(studio, n).y);
  for (double e : exact) mean += e / exact.size();
  for (std::size_t i = 0; i < normals.size(); ++i) {
    const double error = std::abs(evaluateEnvironment(convolved, normals[i]).y - exact[i]) / mean;
    worst = std::max(worst, error);
    squares += error * error / normals.size();
  }
  std::cout << "[ measured ] studio irradiance, SH against brute force: worst " << worst << ", RMS "
            << std::sqrt(squares) << " of the mean " << mean << "\n";
  EXPECT_LT(worst, 0.10);
  EXPECT_LT(std::sqrt(squares), 0.045);
}

TEST(SkyAlbedo, ItsPartsFromTheViewersSideAndFromBehindAddUpToIt) {
  const HairMaterial m;
  for (FibreModel model : {FibreModel::Physical, FibreModel::Marschner}) {
    const glm::dvec3 whole = skyAlbedo(model, m);
    const glm::dvec3 front = skyAlbedoOver(model, m, 0.0, 0.5 * kPiValue);
    const glm::dvec3 back = skyAlbedoOver(model, m, 0.5 * kPiValue, kPiValue);
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(front[c] + back[c], whole[c], 1e-3 * whole[c]);  // quadratures over other panels: 2e-4 seen
      EXPECT_GT(front[c], 0.0);
      EXPECT_GT(back[c], 0.0);
    }
  }
}

namespace {
// A uniform sky of radiance 0.1 with a disc of radius `radiusDeg` and radiance 50 around `axis` (the sun).
EnvironmentMap skyWithSun(const glm::dvec3& axis, double radiusDeg) {
  const double cosRadius = std::cos(glm::radians(radiusDeg));
  return mapOf(512, 256, [&](glm::dvec3 d) { return glm::dvec3(glm::dot(d, axis) > cosRadius ? 50.0 : 0.1); });
}
}  // namespace

TEST(EnvironmentSplit, TheSunBecomesALightAndTheSkyStaysInTheHarmonics) {
  const glm::dvec3 axis = glm::normalize(glm::dvec3(0.4, 0.8, 0.45));
  const EnvironmentMap map = skyWithSun(axis, 3.0);
  const EnvironmentSplit split = splitEnvironment(map);
  ASSERT_EQ(split.lights.size(), 1u);  // nothing else is bright
  const EnvironmentLight& sun = split.lights[0];
  EXPECT_GT(glm::dot(sun.direction, axis), std::cos(glm::radians(0.3)));
  const double discSolidAngle = 2.0 * kPiValue * (1.0 - std::cos(glm::radians(3.0)));
  EXPECT_NEAR(sun.irradiance.g, 50.0 * discSolidAngle, 0.03 * 50.0 * discSolidAngle);  // texels on the rim
  EXPECT_NEAR(sun.solidAngle, discSolidAngle, 0.03 * discSolidAngle);
  // The residual is the sky with a dark hole where the sun was: its mean is 0.1 less the hole's share.
  const double mean = evaluateEnvironment(split.residual, axis).g;
  EXPECT_NEAR(mean, 0.1, 0.01);
  // What the lights took and what stayed add up to the whole map (band 0: the mean, direction-free).
  const EnvironmentSH whole = projectEnvironment(map);
  const double y0 = 0.2820948;
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(split.residual[0][c] + y0 * sun.irradiance[c], whole[0][c], 1e-6 * whole[0][c]);
}

// A sun whose gathered irradiance passes what a light may be (light_limits.h) is refused naming the
// environment, not taken as a light a frame then refuses by index.
TEST(EnvironmentSplit, ASunBrighterThanALightMayBeIsRefused) {
  EnvironmentMap map = skyWithSun(glm::normalize(glm::dvec3(0.4, 0.8, 0.45)), 3.0);
  for (glm::vec3& t : map.texels) t *= 100.0f;  // the sun's radiance 5,000
  map.intensity = 1000.0;                       // its irradiance ~43,000
  try {
    splitEnvironment(map);
    ADD_FAILURE() << "a sun past the light bound was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("environment: a bright region becomes a light of"), std::string::npos) << e.what();
  }
  map.intensity = 20.0;  // ~860: within the bound
  EXPECT_EQ(splitEnvironment(map).lights.size(), 1u);
}

TEST(EnvironmentSplit, TheStudioGivesItsRimAndItsSoftBoxBrightestFirst) {
  const EnvironmentSplit split = splitEnvironment(studioEnvironment());
  ASSERT_EQ(split.lights.size(), 2u);
  const glm::dvec3 rim = glm::normalize(glm::dvec3(0.15, 0.7, -0.7)), box = glm::normalize(glm::dvec3(-0.7, 0.35, 0.65));
  EXPECT_GT(glm::dot(split.lights[0].direction, rim), std::cos(glm::radians(2.0)));
  EXPECT_GT(glm::dot(split.lights[1].direction, box), std::cos(glm::radians(2.0)));
  EXPECT_EQ(splitEnvironment(studioEnvironment(), {1}).lights.size(), 1u);
}

TEST(EnvironmentSplit, WithoutLightsTheHarmonicsHoldEverythingAndBadSettingsAreRefused) {
  const EnvironmentMap studio = studioEnvironment(64, 32);
  const EnvironmentSplit split = splitEnvironment(studio, {0});
  EXPECT_TRUE(split.lights.empty());
  const EnvironmentSH whole = projectEnvironment(studio);
  for (std::size_t i = 0; i < whole.size(); ++i)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(split.residual[i][c], whole[i][c], 1e-9);
  EXPECT_THROW(splitEnvironment(studio, {5}), Error);
  EXPECT_THROW(splitEnvironment(studio, {2, 0.0}), Error);
  EXPECT_THROW(splitEnvironment(studio, {2, 4.0, 0.0}), Error);
  EXPECT_THROW(splitEnvironment(studio, {2, 4.0, std::nan("")}), Error);
}

TEST(EnvironmentSH, RotationCarriesADirectionsProjectionExactly) {
  // The projection of a direction d (a delta of unit weight) is Y_i(d); seen in axes turned by R it is Y_i(R^T d).
  const glm::dmat3 rotation = glm::dmat3(glm::rotate(glm::dmat4(1.0), 0.7, glm::normalize(glm::dvec3(0.3, -0.8, 0.5))));
  for (const glm::dvec3& d : {glm::dvec3(0, 1, 0), glm::normalize(glm::dvec3(0.5, 0.8, 0.6)), glm::normalize(glm::dvec3(-1, -2, 3))}) {
    EnvironmentSH sh{}, expected{};
    addToEnvironment(sh, d, glm::dvec3(1.0, 2.0, 3.0));
    addToEnvironment(expected, glm::transpose(rotation) * d, glm::dvec3(1.0, 2.0, 3.0));
    const EnvironmentSH turned = rotateEnvironment(sh, rotation);
    for (std::size_t i = 0; i < turned.size(); ++i)
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(turned[i][c], expected[i][c], 1e-6) << "coefficient " << i;
  }
  // The identity keeps any coefficients; a uniform sky is the same in any axes.
  EnvironmentSH any{};
  for (std::size_t i = 0; i < any.size(); ++i) any[i] = glm::dvec3(0.1 * double(i) - 0.3, 0.2, -0.05 * double(i));
  const EnvironmentSH same = rotateEnvironment(any, glm::dmat3(1.0));
  for (std::size_t i = 0; i < any.size(); ++i) EXPECT_NEAR(glm::length(same[i] - any[i]), 0.0, 1e-6);
  const EnvironmentSH sky = uniformEnvironmentSH(glm::dvec3(0.06));
  EXPECT_NEAR(glm::length(rotateEnvironment(sky, rotation)[0] - sky[0]), 0.0, 1e-6);
}
