#version 460
// The application's backdrop: a wall behind the heads, one quad of 4 vertices (a triangle strip) from
// gl_VertexIndex, in world space.
layout(push_constant) uniform Push {
  mat4 viewProj;
  vec4 lightDirection;  // xyz: toward the key light
  vec4 lightColor;      // rgb x intensity
  vec4 hairParams;      // Renderer::HairShadows: k, bias, deep
  vec4 hairForward;     // Instance::hairShadowForward: albedo, weight
};
layout(location = 0) out vec3 world;

void main() {
  vec2 corner = vec2(float(gl_VertexIndex & 1), float(gl_VertexIndex >> 1));
  world = vec3(mix(-0.7, 0.9, corner.x), mix(-0.45, 0.45, corner.y), -0.2);
  gl_Position = viewProj * vec4(world, 1.0);
}
