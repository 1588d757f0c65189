#pragma once
// Contract: poses of a CharacterMesh's skeleton and what they do to its vertices (linear blend skinning).
// A pose is one local transform per joint (translation, rotation, scale, as glTF keeps them); the rest pose
// is the skeleton's own, and samplePose overrides the joints a clip drives at a time (clamped to the clip:
// linear between keys, spherical for rotations along the shorter arc; step keys hold). skinningMatrices
// gives per joint the head-space matrix that takes a bind-pose vertex to the posed one:
// modelToHead * global(joint) * inverseBind * inverse(modelToHead); skinMesh applies them with the weights.
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <span>
#include <string>
#include <vector>

#include "engine/core/hair/character_mesh.h"

namespace hp {
struct JointPose {
  glm::vec3 translation{0.0f};
  glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
  glm::vec3 scale{1.0f};
};

// A local transform as a matrix: translation * rotation * scale.
glm::mat4 jointMatrix(const JointPose& pose);
std::vector<JointPose> restPose(const CharacterMesh& mesh);
// Throws hp::Error naming the clips there are when none is called `name`.
const AnimationClip& findClip(const CharacterMesh& mesh, const std::string& name);
std::vector<JointPose> samplePose(const CharacterMesh& mesh, const AnimationClip& clip, float seconds);

// One matrix per joint, head space (identity for every joint in the rest pose of a glTF whose inverse
// binds are its rest globals' inverses).
std::vector<glm::mat4> skinningMatrices(const CharacterMesh& mesh, std::span<const JointPose> pose);

// The mesh's vertices and unit normals under `matrices` (one per joint). A rigid mesh is returned as it is.
struct SkinnedVertices {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;
};
SkinnedVertices skinMesh(const CharacterMesh& mesh, std::span<const glm::mat4> matrices);
}  // namespace hp
