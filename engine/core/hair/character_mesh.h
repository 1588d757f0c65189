#pragma once
// Contract: a character's mesh as hairpipe reads it from a file (OBJ, PLY, glTF 2.0, TressFX .tfxmesh;
// mesh_file.h): the surface the hair's roots bind to, that the hair collides with and that is drawn as the
// head. Positions and normals are in head space (the model's ModelTransform applied, so the hair and its
// mesh share one space as their files do); triangles are counter-clockwise seen from outside, none
// degenerate, every index in range, every normal unit length. A skinned mesh also has per vertex four
// joints and weights summing to 1, a skeleton and its animation clips, all in the file's own (model)
// space: skinningMatrices (skeleton_pose.h) turns a pose into head-space matrices through modelToHead.
// Built only through finishCharacterMesh, which checks all of the above and names the source.
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace hp {
struct Joint {
  std::string name;
  std::int32_t parent = -1;              // index into the skeleton, or -1
  glm::mat4 parentRest{1.0f};            // fixed nodes between the parent joint (or the model) and this joint
  glm::mat4 inverseBind{1.0f};           // model space to the joint's space in the bind pose
  glm::vec3 translation{0.0f};           // the rest pose, local to the parent
  glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
  glm::vec3 scale{1.0f};
};

struct AnimationChannel {
  enum class Path { Translation, Rotation, Scale };
  enum class Interpolation { Linear, Step };
  std::uint32_t joint = 0;
  Path path = Path::Translation;
  Interpolation interpolation = Interpolation::Linear;
  std::vector<float> times;         // seconds, non-decreasing, finite
  std::vector<glm::vec4> values;    // one per time: xyz (translation, scale) or a unit quaternion xyzw
};

struct AnimationClip {
  std::string name;
  float duration = 0.0f;  // the last key time of any channel
  std::vector<AnimationChannel> channels;
};

struct CharacterMesh {
  std::string source;  // the file, for messages
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;
  std::vector<glm::uvec3> triangles;
  std::uint32_t droppedDegenerateTriangles = 0;
  // Skinning: empty, or one per vertex (joints index `skeleton`; unused slots weigh 0).
  std::vector<glm::uvec4> joints;
  std::vector<glm::vec4> weights;
  std::vector<Joint> skeleton;  // parents before children
  std::vector<AnimationClip> animations;
  glm::mat4 modelToHead{1.0f};  // the ModelTransform the positions went through

  bool skinned() const { return !weights.empty(); }
  std::uint32_t vertexCount() const { return static_cast<std::uint32_t>(positions.size()); }
  std::uint32_t triangleCount() const { return static_cast<std::uint32_t>(triangles.size()); }
};

// Validates a mesh whose positions, triangles (and optionally normals, joints, weights, skeleton,
// animations) a reader filled, in head space: throws hp::Error naming mesh.source and the first problem
// (a non-finite value, an index out of range, a joint past the skeleton, weights negative or summing to
// 0, a parent after its child, a clip's keys out of order, no triangle left). Drops zero-area triangles
// (counted), computes area-weighted normals when none were given, normalises normals and weights.
void finishCharacterMesh(CharacterMesh& mesh);

// The largest vertex count, triangle count, joint count and animation key count a reader accepts
// (far above a real character; each reader checks its counts against these before allocating).
inline constexpr std::uint64_t kMaxMeshVertices = 1u << 24;
inline constexpr std::uint64_t kMaxMeshTriangles = 1u << 25;
inline constexpr std::uint64_t kMaxMeshJoints = 1024;
inline constexpr std::uint64_t kMaxAnimationKeys = 1u << 24;
}  // namespace hp
