#version 460
// hair_shadows.glsl's hairpipeShadowAlpha (public/hairpipe/, included by shared/opacity.h) at given slice coordinates, in the one texel of a 1 x 1 map (whose
// filtered value is the texel's own), for tests/render/opacity_lookup_test.cpp.
#include "shared/selftest.h"
#include "common.glsl"
#include "shared/opacity.h"

layout(local_size_x = LOOKUP_WORKGROUP_SIZE) in;
layout(binding = LOOKUP_BINDING_MAPS) uniform sampler2DArray maps;
layout(std430, binding = LOOKUP_BINDING_QUERIES) readonly buffer Queries { vec4 queries[]; };
layout(std430, binding = LOOKUP_BINDING_RESULTS) writeonly buffer Results { float results[]; };
layout(push_constant) uniform Push { ScanPush push; };

void main() {
  uint i = hpThreadId(LOOKUP_WORKGROUP_SIZE);
  if (i >= push.count) return;
  vec4 q = queries[i];
  results[i] = hairpipeShadowAlpha(maps, 0u, vec3(0.5, 0.5, 1.0), q.x, q.z > 0.5, q.y);
}
