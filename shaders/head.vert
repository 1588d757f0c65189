#version 460
// The opaque head mesh, pulled by index from its position/normal buffers.
#include "shared/render.h"

layout(std140, binding = RENDER_BINDING_FRAME) uniform Frame { RenderFrame frame; };
layout(std430, binding = RENDER_BINDING_POSITIONS) readonly buffer Positions { vec4 positions[]; };
layout(std430, binding = RENDER_BINDING_TANGENTS) readonly buffer Normals { vec4 normals[]; };
layout(std430, binding = RENDER_BINDING_ATTRIBUTES) readonly buffer Indices { uint indices[]; };
layout(push_constant) uniform Push { mat4 headToWorld; };

layout(location = 0) out vec3 outNormal;
layout(location = 1) out float outScalp;  // 1 where hair grows
layout(location = 2) out vec3 outWorld;   // the lights and shadows are looked up per fragment

void main() {
  uint i = indices[gl_VertexIndex];
  vec4 world = headToWorld * vec4(positions[i].xyz, 1.0);
  outNormal = mat3(headToWorld) * normals[i].xyz;
  outScalp = normals[i].w;
  outWorld = world.xyz;
  gl_Position = frame.proj * frame.view * world;
}
