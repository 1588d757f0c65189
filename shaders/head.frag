#version 460
// The head: per light of the frame, diffuse with the paper's wrap term (wrap + N.L) / (1 + wrap) (L, cone
// and distance scale from shared/light.h), plus its indirect light (head.vert: the sky past its own shape and
// its skin's bounce), or without that the environment's open irradiance / pi (environment.glsl);
// hair-coloured where hair grows. Each light's direct term is shadowed by the hair (its slot's opacity maps,
// T = hairTransmittance(k alpha): exp(-k alpha) and, with dual scattering, the light the hair passes on
// forward; looked up over a few texels) and by the heads (their depth map): frame_shadows.glsl.
#include "shared/render.h"

layout(std140, binding = RENDER_BINDING_FRAME) readonly buffer Frame { RenderFrame frame; };
layout(binding = RENDER_BINDING_OPACITY) uniform sampler2DArray opacityMaps;
layout(binding = RENDER_BINDING_HEAD_SHADOW) uniform sampler2DArrayShadow headShadowMap;
layout(std430, binding = RENDER_BINDING_LIGHT) readonly buffer Light { LightSpace lightSpaces[]; };
layout(location = 0) in vec3 inNormal;
layout(location = 1) in float inScalp;
layout(location = 2) in vec3 inWorld;
layout(location = 3) in vec3 inIndirect;
layout(location = 0) out vec4 outColor;
#include "frame_shadows.glsl"
#include "environment.glsl"

// 1: every light in a loop; 0: the first light only, without the loop (twice as fast on lavapipe, whose
// loops run this body at half speed: compute/head/head_pass.h takes it for frames of one light).
layout(constant_id = 0) const uint HEAD_LIGHT_LOOP = 1u;

// One light's diffuse term, shadowed.
vec3 headLight(FrameLight light, vec3 N, float wrap) {
  LightSample ls = sampleLight(light, inWorld);
  float nl = dot(N, ls.L);
  float diffuse = ls.scale * max((wrap + nl) / (1.0 + wrap), 0.0);
  // Past the wrap term's reach (or outside a spot's cone) the light adds nothing, whatever stands in its way:
  // skip the shadow lookups (the skin facing away from the light; GPUs branch by the warp, so a region of it).
  if (!(diffuse > 0.0)) return vec3(0.0);
  // Only skin facing away from the light is in the map of back faces (with a fade across the terminator for
  // the interpolated normal): lit skin keeps the base offset and its contact shadows.
  float c = abs(nl);
  float slopeTan = (1.0 - smoothstep(-0.05, 0.1, nl)) * sqrt(max(1.0 - c * c, 0.0)) / max(c, 1e-3);
  LightShadow shadow = frameLightShadow(light, inWorld, ls.L, true, slopeTan);
  return light.radiance.rgb * hairTransmittance(frame.strand.z * shadow.alpha) * (diffuse * shadow.head);
}

void main() {
  vec3 N = normalize(inNormal);
  float wrap = frame.skinColor.w;
  // Under the hair the scalp takes the hair's albedo, darkened as the hair's own shadow would.
  vec3 albedo = mix(frame.skinColor.rgb, 0.5 * frame.hairColor.rgb, inScalp);
  vec3 direct = vec3(0.0);
  if (HEAD_LIGHT_LOOP != 0u) {
    for (uint i = 0u; i < frame.lightCount.x; ++i) direct += headLight(frame.lights[i], N, wrap);
  } else if (frame.lightCount.x > 0u) {
    direct = headLight(frame.lights[0], N, wrap);
  }
  // The indirect light from the head's transfer (head.vert), else the open sky around N.
  vec3 indirect = frame.skinSky[0].w != 0.0 ? inIndirect : environmentLight(N);
  outColor = vec4(albedo * (direct / 3.14159265 + indirect), 1.0);
}
