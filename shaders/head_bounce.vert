#version 460
// The head bounce map (compute/shadows/head_bounce_map.h): the head mesh seen from the light, framed like its
// depth shadow map (RenderFrame::headShadowViewProj), pulled by index like head.vert.
#include "shared/render.h"
#include "opacity_lookup.glsl"

// A storage block: the instance's head bounce frame block (compute/renderer/hair_instance.h), written on the device.
layout(std140, binding = RENDER_BINDING_FRAME) readonly buffer Frame { RenderFrame frame; };
layout(std430, binding = RENDER_BINDING_POSITIONS) readonly buffer Positions { vec4 positions[]; };
layout(std430, binding = RENDER_BINDING_TANGENTS) readonly buffer Normals { vec4 normals[]; };
layout(std430, binding = RENDER_BINDING_ATTRIBUTES) readonly buffer Indices { uint indices[]; };
layout(std430, binding = RENDER_BINDING_LIGHT) readonly buffer Light { LightSpace light; };
layout(push_constant) uniform Push { mat4 headToWorld; };

layout(location = 0) out vec3 outNormal;
layout(location = 1) out float outScalp;
layout(location = 2) out vec3 outLightUvw;
layout(location = 3) out vec4 outSliceWeights[4];
layout(location = 7) out vec3 outWorld;
layout(location = 8) out float outSlice;

void main() {
  uint i = indices[gl_VertexIndex];
  vec4 world = headToWorld * vec4(positions[i].xyz, 1.0);
  outNormal = mat3(headToWorld) * normals[i].xyz;
  outScalp = normals[i].w;
  OpacityVertex o = opacityVertex(light, world.xyz, frame.strand.w, frame.options.y != 0u);
  outLightUvw = o.uvw;
  outSlice = o.s;
  outWorld = world.xyz;
  outSliceWeights = vec4[4](o.w0, o.w1, o.w2, o.w3);
  gl_Position = frame.headShadowViewProj * world;
}
