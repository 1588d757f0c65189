#version 460
// The head's depth shadow map: the head mesh (pulled by index) seen from the light; the pipeline culls
// front faces, so the map holds the back faces' depth (shaders/head_shadow.glsl). No fragment shader.
#include "shared/render.h"

layout(std430, binding = OPACITY_BINDING_POSITIONS) readonly buffer Positions { vec4 positions[]; };
layout(std430, binding = OPACITY_BINDING_INDICES) readonly buffer Indices { uint indices[]; };
layout(push_constant) uniform Push { mat4 headToLightClip; };

void main() {
  gl_Position = headToLightClip * vec4(positions[indices[gl_VertexIndex]].xyz, 1.0);
}
