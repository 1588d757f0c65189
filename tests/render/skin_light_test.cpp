// The frame's light for the skin's transfer (compute/raster/frame_block.h setSkinLight): the sky and the lights
// as radiance SH in the head's own axes, so that a turned head sees the same world.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "compute/raster/frame_block.h"
#include "engine/core/shading/environment_sh.h"
#include "shaders/shared/environment.h"

using namespace hp;

namespace {
glm::vec3 shAt(const glm::vec4 (&sh)[gpu::ENV_SH_COEFFICIENTS], const glm::vec3& n) {
  glm::vec3 sum(0.0f);
  for (std::uint32_t i = 0; i < gpu::ENV_SH_COEFFICIENTS; ++i) sum += glm::vec3(sh[i]) * gpu::envShBasis(i, n);
  return sum;
}
}  // namespace

TEST(SkinLight, TheSkyAndTheLightsAreTurnedIntoTheHeadsAxes) {
  // A head turned 70 degrees about a tilted axis, moved and scaled by 2 (the scale is divided out).
  const glm::mat3 turn = glm::mat3(glm::rotate(glm::mat4(1.0f), glm::radians(70.0f), glm::normalize(glm::vec3(0.2f, 1.0f, -0.4f))));
  glm::mat4 headToWorld = glm::mat4(turn * 2.0f);
  headToWorld[3] = glm::vec4(0.3f, 1.2f, -0.5f, 1.0f);
  render::LookSettings look;
  look.ambient = 0.05f;
  for (std::size_t i = 0; i < look.environment.size(); ++i)
    look.environment[i] = glm::vec3(0.02f * float(i) - 0.05f, 0.03f, 0.01f * float(i % 3));
  LightSpec sun;  // directional, toward (0.5, 0.8, 0.6)
  sun.color = {1.0f, 0.9f, 0.8f};
  render::FrameLights lights;
  lights.lights = {sun};
  gpu::RenderFrame f{};
  render::setSkinLight(f, headToWorld, glm::vec3(headToWorld[3]), lights, look);
  EXPECT_EQ(f.skinSky[0].w, 1.0f);
  // The sky: what the head sees along its own n is the world's radiance along turn * n.
  EnvironmentSH world = uniformEnvironmentSH(glm::dvec3(look.ambient));
  for (std::size_t i = 0; i < world.size(); ++i) world[i] += glm::dvec3(look.environment[i]);
  for (const glm::vec3& n : {glm::vec3(0, 1, 0), glm::normalize(glm::vec3(1, -2, 0.5f)), glm::normalize(glm::vec3(-0.3f, 0.1f, 1))}) {
    const glm::vec3 expected(evaluateEnvironment(world, glm::dvec3(turn * n)));
    const glm::vec3 got = shAt(f.skinSky, n);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(got[c], expected[c], 1e-5f) << "n " << n.x << " " << n.y << " " << n.z;
  }
  // The sun: a direction of its irradiance, in head axes the world direction turned back.
  const glm::vec3 headSun = glm::transpose(turn) * sun.direction;
  for (std::uint32_t i = 0; i < gpu::ENV_SH_COEFFICIENTS; ++i)
    for (int c = 0; c < 3; ++c)
      EXPECT_NEAR(f.skinLights[i][c], sun.color[c] * sun.intensity * gpu::envShBasis(i, headSun), 1e-5f) << "coefficient " << i;
  // Off: the flag is cleared (head.frag takes the open sky).
  look.skinIndirect = false;
  render::setSkinLight(f, headToWorld, glm::vec3(headToWorld[3]), lights, look);
  EXPECT_EQ(f.skinSky[0].w, 0.0f);
}

// At the given centre (the head's bounding sphere's, not its origin): 1 unit from the light, a quarter of it.
TEST(SkinLight, APointLightArrivesAtTheHeadsCentreWithItsFalloff) {
  const LightSpec point = LightSpec::makePoint({0.0f, 0.0f, 2.0f}, 0.5f);  // 1 at 0.5 units
  render::FrameLights lights;
  lights.lights = {point};
  gpu::RenderFrame f{};
  render::setSkinLight(f, glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, 1.0f), lights, render::LookSettings{});
  const float scale = (0.5f / 1.0f) * (0.5f / 1.0f);
  for (std::uint32_t i = 0; i < gpu::ENV_SH_COEFFICIENTS; ++i)
    EXPECT_NEAR(f.skinLights[i].x, point.color.x * point.intensity * scale * gpu::envShBasis(i, glm::vec3(0, 0, 1)), 1e-6f);
}
