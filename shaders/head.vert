#version 460
// The opaque head mesh, pulled by index from its position/normal buffers, and its skin's indirect light per
// vertex from the mesh's transfer (engine/core/hair/skin_transfer.h) and the frame's head-space light SH:
//   sky     = sum_i (A_l Y_i(n) - occluded_i) skinSky_i          (the sky past the head's own shape)
//   bounced = albedo / max(1 - albedo reflecting, 0.1) sum_i bounce_i (skinSky_i + skinLights_i)
// one bounce off the skin, and each further bounce taken to keep albedo x reflecting of the one before (a
// geometric series, capped at ten times the first bounce). n is the vertex's normal as drawn (posed, for a
// skinned character), so its open lobe turns with it; what the head hides is the mesh's at rest. The sum over
// pi, the light a white Lambertian skin sends back, goes to head.frag.
#include "shared/render.h"

layout(std140, binding = RENDER_BINDING_FRAME) readonly buffer Frame { RenderFrame frame; };
layout(std430, binding = RENDER_BINDING_POSITIONS) readonly buffer Positions { vec4 positions[]; };
layout(std430, binding = RENDER_BINDING_TANGENTS) readonly buffer Normals { vec4 normals[]; };
layout(std430, binding = RENDER_BINDING_ATTRIBUTES) readonly buffer Indices { uint indices[]; };
layout(std430, binding = RENDER_BINDING_SKIN_TRANSFER) readonly buffer SkinTransfer { vec4 skinTransfer[]; };
layout(push_constant) uniform Push { mat4 headToWorld; };

layout(location = 0) out vec3 outNormal;
layout(location = 1) out float outScalp;  // 1 where hair grows
layout(location = 2) out vec3 outWorld;   // the lights and shadows are looked up per fragment
layout(location = 3) out vec3 outIndirect;  // the skin's indirect irradiance / pi (0 when frame.skinSky[0].w is 0)

// Written out in vec4 loads rather than looped (lavapipe runs loops markedly slower: docs/PERFORMANCE.md);
// the five vec4s hold the floats in SKIN_TRANSFER_* order.
vec3 skinIndirect(uint v, vec3 n) {
  uint base = v * (SKIN_TRANSFER_FLOATS / 4u);
  vec4 o0 = skinTransfer[base], o1 = skinTransfer[base + 1u], m = skinTransfer[base + 2u];
  vec4 b1 = skinTransfer[base + 3u], b2 = skinTransfer[base + 4u];
  vec3 open = 3.14159265 * (ENV_COSINE_BAND0 * envShBasis(0u, n) * frame.skinSky[0].rgb +
                            ENV_COSINE_BAND1 * (envShBasis(1u, n) * frame.skinSky[1].rgb + envShBasis(2u, n) * frame.skinSky[2].rgb +
                                                envShBasis(3u, n) * frame.skinSky[3].rgb) +
                            ENV_COSINE_BAND2 * (envShBasis(4u, n) * frame.skinSky[4].rgb + envShBasis(5u, n) * frame.skinSky[5].rgb +
                                                envShBasis(6u, n) * frame.skinSky[6].rgb + envShBasis(7u, n) * frame.skinSky[7].rgb +
                                                envShBasis(8u, n) * frame.skinSky[8].rgb));
  vec3 hidden = o0.x * frame.skinSky[0].rgb + o0.y * frame.skinSky[1].rgb + o0.z * frame.skinSky[2].rgb +
                o0.w * frame.skinSky[3].rgb + o1.x * frame.skinSky[4].rgb + o1.y * frame.skinSky[5].rgb +
                o1.z * frame.skinSky[6].rgb + o1.w * frame.skinSky[7].rgb + m.x * frame.skinSky[8].rgb;
  vec3 bounced = m.y * (frame.skinSky[0].rgb + frame.skinLights[0].rgb) +
                 m.z * (frame.skinSky[1].rgb + frame.skinLights[1].rgb) +
                 m.w * (frame.skinSky[2].rgb + frame.skinLights[2].rgb) +
                 b1.x * (frame.skinSky[3].rgb + frame.skinLights[3].rgb) +
                 b1.y * (frame.skinSky[4].rgb + frame.skinLights[4].rgb) +
                 b1.z * (frame.skinSky[5].rgb + frame.skinLights[5].rgb) +
                 b1.w * (frame.skinSky[6].rgb + frame.skinLights[6].rgb) +
                 b2.x * (frame.skinSky[7].rgb + frame.skinLights[7].rgb) +
                 b2.y * (frame.skinSky[8].rgb + frame.skinLights[8].rgb);
  vec3 albedo = frame.skinColor.rgb;
  bounced *= albedo / max(vec3(1.0) - albedo * b2.z, vec3(0.1));  // b2.z: the reflecting share
  return max(open - hidden + bounced, vec3(0.0)) / 3.14159265;
}

void main() {
  uint i = indices[gl_VertexIndex];
  vec4 world = headToWorld * vec4(positions[i].xyz, 1.0);
  outNormal = mat3(headToWorld) * normals[i].xyz;
  outScalp = normals[i].w;
  outWorld = world.xyz;
  outIndirect = frame.skinSky[0].w != 0.0 ? skinIndirect(i, normalize(normals[i].xyz)) : vec3(0.0);
  gl_Position = frame.proj * frame.view * world;
}
