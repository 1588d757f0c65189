#version 460
// The head bounce map (compute/shadows/head_bounce_map.h): the head mesh seen from the light of shadow slot 0,
// framed like that slot's depth shadow map (RenderFrame::shadows[0]), pulled by index like head.vert.
#include "shared/render.h"

// A storage block: the instance's head bounce frame block (compute/renderer/hair_instance.h), written on the device.
layout(std140, binding = RENDER_BINDING_FRAME) readonly buffer Frame { RenderFrame frame; };
layout(std430, binding = RENDER_BINDING_POSITIONS) readonly buffer Positions { vec4 positions[]; };
layout(std430, binding = RENDER_BINDING_TANGENTS) readonly buffer Normals { vec4 normals[]; };
layout(std430, binding = RENDER_BINDING_ATTRIBUTES) readonly buffer Indices { uint indices[]; };
layout(push_constant) uniform Push { mat4 headToWorld; };

layout(location = 0) out vec3 outNormal;
layout(location = 1) out float outScalp;
layout(location = 2) out vec3 outWorld;

void main() {
  uint i = indices[gl_VertexIndex];
  vec4 world = headToWorld * vec4(positions[i].xyz, 1.0);
  outNormal = mat3(headToWorld) * normals[i].xyz;
  outScalp = normals[i].w;
  outWorld = world.xyz;
  gl_Position = frame.shadows[0].headViewProj * world;
}
