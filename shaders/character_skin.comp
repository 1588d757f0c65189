#version 460
// One invocation per vertex of a skinned character: linear blend skinning (shared/character.h, step 1).
#include "shared/character.h"
#include "common.glsl"

layout(local_size_x = CHARACTER_WORKGROUP_SIZE) in;
layout(push_constant) uniform Push { CharacterParams params; };
layout(std430, binding = CHARACTER_BINDING_REST) readonly buffer Rest { vec4 rest[]; };
layout(std430, binding = CHARACTER_BINDING_SKIN) readonly buffer Skin { CharacterSkin skin[]; };
layout(std430, binding = CHARACTER_BINDING_BONES) readonly buffer Bones { mat4 bones[]; };
layout(std430, binding = CHARACTER_BINDING_POSED) writeonly buffer Posed { vec4 posed[]; };
layout(std430, binding = CHARACTER_BINDING_POSED_NORMALS) writeonly buffer PosedNormals { vec4 posedNormals[]; };

void main() {
  uint v = hpThreadId(CHARACTER_WORKGROUP_SIZE);
  if (v >= params.counts.x) return;
  CharacterSkin s = skin[v];
  mat4 m = s.weights.x * bones[s.bones.x] + s.weights.y * bones[s.bones.y] + s.weights.z * bones[s.bones.z] +
           s.weights.w * bones[s.bones.w];
  posed[v] = vec4((m * vec4(rest[2u * v].xyz, 1.0)).xyz, 1.0);
  // Normals go by the cofactor matrix (the inverse transpose times the determinant: the same direction for the
  // proper transforms skinning makes; a mirroring bone would flip it).
  mat3 a = mat3(m);
  mat3 cofactor = mat3(cross(a[1], a[2]), cross(a[2], a[0]), cross(a[0], a[1]));
  vec4 n = rest[2u * v + 1u];
  vec3 turned = cofactor * n.xyz;
  float len = length(turned);
  posedNormals[v] = vec4(len > 0.0 ? turned / len : n.xyz, n.w);
}
