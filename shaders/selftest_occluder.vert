#version 460
// An application's occluder for tests/render/application_occluders_test.cpp: a quad of four world-space
// corners (a triangle strip) drawn, depth only, into the heads' depth map with Renderer::occluderTargets'
// world-to-clip matrix. No fragment shader.
layout(push_constant) uniform Push {
  mat4 viewProj;
  vec4 corners[4];
};

void main() { gl_Position = viewProj * vec4(corners[gl_VertexIndex].xyz, 1.0); }
