#version 460
#extension GL_GOOGLE_include_directive : require
// An application's receivers lit through the hair, for tests/render/hair_shadows_export_test.cpp: it includes
// the public hair_shadows.glsl and nothing else of hairpipe's GLSL (shared/selftest.h holds only this
// test's bindings), and binds what Renderer::hairShadows() hands out, as an engine's shader would.
#include "public/hairpipe/hair_shadows.glsl"
#include "shared/selftest.h"

layout(local_size_x = 64) in;
layout(binding = HAIR_SHADOW_TEST_BINDING_MAPS) uniform sampler2DArray hairShadowMaps;
layout(std430, binding = HAIR_SHADOW_TEST_BINDING_LIGHTS) readonly buffer HairLights { HairpipeLightSpace hairLights[]; };
layout(std430, binding = HAIR_SHADOW_TEST_BINDING_POINTS) readonly buffer Points { vec4 points[]; };
layout(std430, binding = HAIR_SHADOW_TEST_BINDING_RESULTS) writeonly buffer Results { vec4 results[]; };
layout(push_constant) uniform Push { HairShadowTestPush push; };

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= push.count) return;
  vec3 p = points[i].xyz;
  HairpipeLightSpace light = hairLights[push.slot];
  vec3 t = hairpipeHairShadow(hairShadowMaps, light, push.slot, p, push.params, push.forward);
  HairpipeShadowPoint q = hairpipeShadowPoint(light.viewProj, p);
  results[i] = vec4(t, hairpipeShadowAlpha(hairShadowMaps, push.slot, q.uvw, q.s, push.params.z != 0.0, push.params.y));
}
