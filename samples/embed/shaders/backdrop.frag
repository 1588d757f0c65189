#version 460
#extension GL_GOOGLE_include_directive : require
// The backdrop lit by the key light through the hair: the light hairpipe's opacity maps let through
// (shadow slot 0: the first shadowed light), from the installed <hairpipe/hair_shadows.glsl>.
#include <hairpipe/hair_shadows.glsl>

layout(push_constant) uniform Push {
  mat4 viewProj;
  vec4 lightDirection;
  vec4 lightColor;
  vec4 hairParams;
  vec4 hairForward;
};
layout(set = 0, binding = 0) uniform sampler2DArray hairShadowMaps;
layout(std430, set = 0, binding = 1) readonly buffer HairLights { HairpipeLightSpace hairLights[]; };
layout(location = 0) in vec3 world;
layout(location = 0) out vec4 color;

void main() {
  const vec3 albedo = vec3(0.55, 0.6, 0.65), normal = vec3(0.0, 0.0, 1.0);
  vec3 throughHair = hairpipeHairShadow(hairShadowMaps, hairLights[0], 0u, world, hairParams, hairForward);
  vec3 direct = lightColor.rgb * max(dot(normal, lightDirection.xyz), 0.0) * throughHair;
  color = vec4(albedo * (0.15 + direct / 3.14159265), 1.0);  // linear, as hairpipe's heads write it
}
