// Compiles the analytic part of shaders/marschner.glsl as C++ in double precision and compares it
// with the exact reference: this checks the LOGIC of the GLSL port (roots, caustic, lobes) on the
// CPU. Single-precision behaviour is checked on the GPU by the brdf_eval kernel.
#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include <cmath>
#include <random>

#include "engine/core/shading/marschner.h"
#include "tests/shading/random_directions.h"

namespace glsl_port {
using namespace glm;
using vec3 = glm::dvec3;
using vec4 = glm::dvec4;
struct MarschnerParams {  // mirrors shaders/shared/marschner.h with double members
  vec4 absorption, longitudinal, caustic, mScale, n0Scale, n1Scale;
  glm::uvec4 control;
};
inline vec4 marschnerAngles(vec3 L, vec3 V, vec3 T) {
  hp::ShadingAngles a = hp::shadingAngles(L, V, T);
  return vec4(a.sinThetaI, a.sinThetaR, a.cosPhi, 0.0);
}
#define MARSCHNER_GLSL_AS_CPP
#define float double
#define out
#include "shaders/marschner.glsl"
#undef out
#undef float
}  // namespace glsl_port

TEST(GlslPort, DirectModeLogicMatchesTheExactS) {
  hp::HairMaterial m;
  std::vector<hp::HairMaterial> materials(3, m);
  materials[1].eta = 1.3;
  materials[1].absorption = {0.1, 0.2, 0.3};
  materials[2].eta = 2.2;
  for (const hp::HairMaterial& mat : materials) {
    glsl_port::MarschnerParams p{};
    p.absorption = {mat.absorption, mat.eta};
    p.longitudinal = {mat.alphaR, mat.betaR, mat.kG, mat.wc};
    p.caustic = {mat.dEta, mat.dhM, 0, 0};
    std::mt19937_64 rng(3);
    int bad = 0;
    for (int i = 0; i < 20000; ++i) {
      auto t = hp::test::uniformTriple(rng);
      glm::dvec3 a = glsl_port::marschnerDirect(t.L, t.V, t.T, p);
      glm::dvec3 b = hp::marschnerS(t.L, t.V, t.T, mat);
      for (int c = 0; c < 3; ++c)
        if (!(std::abs(a[c] - b[c]) <= 1e-9 * std::abs(b[c]) + 1e-12)) ++bad;
    }
    EXPECT_EQ(bad, 0) << "eta " << mat.eta;
  }
}
