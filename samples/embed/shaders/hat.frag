#version 460
// The flat cap in the application's view: one colour (its lighting is not what the sample shows).
layout(push_constant) uniform Push {
  mat4 transform;  // the head's axes to clip space: viewProj x the head's placement
  vec4 disc;
  vec4 color;
};
layout(location = 0) out vec4 outColor;

void main() { outColor = vec4(color.rgb, 1.0); }
