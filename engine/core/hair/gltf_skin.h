#pragma once
// Contract: the parts of a parsed glTF that gltf_mesh.cpp builds a CharacterMesh from: the node graph of
// the default scene (each node's parent and rest transform; a child named twice, a cycle or a bad index is
// refused), the mesh instances it holds and the one skin they use; that skin's joints as a skeleton with
// parents first; the joints a rigid primitive follows; the animation channels that drive the joints.
// Errors are hp::Error naming the source and the node, skin or animation.
#include "engine/core/hair/tinygltf_config.h"

#include <glm/glm.hpp>

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "engine/core/hair/character_mesh.h"

namespace hp {
struct GltfScene {
  std::vector<int> parent;                    // per node, -1 for a root
  std::vector<glm::mat4> global;              // per node, the rest pose in model space
  std::vector<std::pair<int, int>> instances;  // (node, mesh) of the scene's nodes, in visiting order
  std::vector<int> order;                     // every node, parents before children
  int skin = -1;                              // the skin the instances use, or -1
};
GltfScene gltfScene(const tinygltf::Model& model, const std::string& source);

struct GltfSkeleton {
  std::vector<Joint> joints;             // parents first
  std::vector<std::uint32_t> remap;      // position in the skin's joint list -> index in joints
  std::map<int, std::uint32_t> ofNode;   // a joint's node -> index in joints
  std::vector<int> nodeOf;               // per joint its node (-1: the static joint)
  std::vector<int> jointAtOrAbove;       // per node the nearest joint node at or above it, or -1
};
GltfSkeleton gltfSkeleton(const tinygltf::Model& model, const GltfScene& scene, const std::string& source);
// The joint a rigid primitive of `node` follows: its nearest joint ancestor (or itself), else a joint
// "<static>" that never moves (added once). Its vertices then belong in that joint's bind space.
std::int32_t rigidJointOf(GltfSkeleton& skeleton, const GltfScene& scene, int node);

// At most kMaxAnimationKeys keys over all channels and kMaxClips clips with channels; more is refused.
inline constexpr std::size_t kMaxClips = 1024;
std::vector<AnimationClip> gltfAnimations(const tinygltf::Model& model, const GltfSkeleton& skeleton,
                                          const std::string& source);
}  // namespace hp
