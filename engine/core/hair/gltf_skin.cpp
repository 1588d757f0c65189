// glTF node graph, skin and animations (docs/THEORY.md §8.5).
#include "engine/core/hair/gltf_skin.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/gtx/matrix_decompose.hpp>

#include <algorithm>
#include <cmath>
#include <deque>

#include "engine/core/error.h"
#include "engine/core/hair/gltf_accessor.h"
#include "engine/core/hair/input_file.h"
#include "engine/core/hair/skeleton_pose.h"

namespace hp {
namespace {
std::string nodeName(const tinygltf::Model& model, int node) {
  const std::string& name = model.nodes[std::size_t(node)].name;
  return "node " + std::to_string(node) + (name.empty() ? "" : " (" + excerpt(name) + ")");
}

JointPose restOf(const tinygltf::Node& n, const std::string& what) {
  JointPose p;
  if (n.matrix.size() == 16) {
    glm::mat4 m;
    for (int i = 0; i < 16; ++i) glm::value_ptr(m)[i] = float(n.matrix[std::size_t(i)]);
    glm::vec3 skew;
    glm::vec4 perspective;
    if (!glm::decompose(m, p.scale, p.rotation, p.translation, skew, perspective))
      throw Error(what + "'s matrix is not a rotation, scale and translation");
    return p;
  }
  if ((!n.matrix.empty()) || (n.translation.size() != 0 && n.translation.size() != 3) ||
      (n.rotation.size() != 0 && n.rotation.size() != 4) || (n.scale.size() != 0 && n.scale.size() != 3))
    throw Error(what + " has a transform of the wrong size");
  if (n.translation.size() == 3) p.translation = glm::vec3(n.translation[0], n.translation[1], n.translation[2]);
  if (n.scale.size() == 3) p.scale = glm::vec3(n.scale[0], n.scale[1], n.scale[2]);
  if (n.rotation.size() == 4) {
    const glm::quat q(float(n.rotation[3]), float(n.rotation[0]), float(n.rotation[1]), float(n.rotation[2]));
    if (!(glm::length(q) > 1e-6f)) throw Error(what + " has a zero rotation quaternion");
    p.rotation = glm::normalize(q);
  }
  return p;
}

std::vector<int> parentsOf(const tinygltf::Model& model, const std::string& source) {
  std::vector<int> parent(model.nodes.size(), -1);
  for (std::size_t i = 0; i < model.nodes.size(); ++i)
    for (int c : model.nodes[i].children) {
      if (c < 0 || std::size_t(c) >= model.nodes.size() || std::size_t(c) == i || parent[std::size_t(c)] >= 0)
        throw Error(source + ": node " + std::to_string(i) + "'s child " + std::to_string(c) +
                    " is not a node, is itself or has another parent");
      parent[std::size_t(c)] = int(i);
    }
  return parent;
}

std::vector<int> sceneRoots(const tinygltf::Model& model, const std::vector<int>& parent, const std::string& source) {
  std::vector<int> roots;
  if (model.scenes.empty()) {
    for (std::size_t i = 0; i < parent.size(); ++i)
      if (parent[i] < 0) roots.push_back(int(i));
    return roots;
  }
  const int s = model.defaultScene >= 0 ? model.defaultScene : 0;
  if (std::size_t(s) >= model.scenes.size()) throw Error(source + ": the default scene " + std::to_string(s) + " is not a scene");
  for (int n : model.scenes[std::size_t(s)].nodes) {
    if (n < 0 || std::size_t(n) >= parent.size() || parent[std::size_t(n)] >= 0)
      throw Error(source + ": scene node " + std::to_string(n) + " is not a root node");
    roots.push_back(n);
  }
  return roots;
}
}  // namespace

GltfScene gltfScene(const tinygltf::Model& model, const std::string& source) {
  GltfScene scene;
  scene.parent = parentsOf(model, source);
  // Every node's rest transform, roots first; a node reachable from no root is on a cycle.
  scene.global.assign(model.nodes.size(), glm::mat4(1.0f));
  std::vector<bool> done(model.nodes.size(), false);
  std::deque<int> queue;
  for (std::size_t i = 0; i < model.nodes.size(); ++i)
    if (scene.parent[i] < 0) queue.push_back(int(i));
  while (!queue.empty()) {
    const int n = queue.front();
    queue.pop_front();
    const glm::mat4 parent = scene.parent[std::size_t(n)] >= 0 ? scene.global[std::size_t(scene.parent[std::size_t(n)])] : glm::mat4(1.0f);
    scene.global[std::size_t(n)] = parent * jointMatrix(restOf(model.nodes[std::size_t(n)], source + ": " + nodeName(model, n)));
    done[std::size_t(n)] = true;
    scene.order.push_back(n);
    for (int c : model.nodes[std::size_t(n)].children) queue.push_back(c);
  }
  if (const auto it = std::find(done.begin(), done.end(), false); it != done.end())
    throw Error(source + ": " + nodeName(model, int(it - done.begin())) + " is on a cycle of nodes");
  // The scene's mesh instances, depth first from its roots.
  std::vector<int> stack = sceneRoots(model, scene.parent, source);
  std::reverse(stack.begin(), stack.end());
  while (!stack.empty()) {
    const int n = stack.back();
    stack.pop_back();
    const tinygltf::Node& node = model.nodes[std::size_t(n)];
    if (node.mesh >= 0) {
      if (std::size_t(node.mesh) >= model.meshes.size()) throw Error(source + ": " + nodeName(model, n) + " names a mesh that is not there");
      if (node.skin >= 0 && std::size_t(node.skin) >= model.skins.size()) throw Error(source + ": " + nodeName(model, n) + " names a skin that is not there");
      if (node.skin >= 0 && scene.skin >= 0 && node.skin != scene.skin)
        throw Error(source + ": meshes use two skins (" + std::to_string(scene.skin) + " and " + std::to_string(node.skin) + "); hairpipe reads one skeleton per character");
      if (node.skin >= 0) scene.skin = node.skin;
      scene.instances.emplace_back(n, node.mesh);
    }
    for (auto c = node.children.rbegin(); c != node.children.rend(); ++c) stack.push_back(*c);
  }
  return scene;
}

namespace {
// The skin's inverse bind matrices, one per joint (identity when the skin has none).
std::vector<glm::mat4> inverseBinds(const tinygltf::Model& model, const tinygltf::Skin& skin, const std::string& source) {
  std::vector<glm::mat4> out(skin.joints.size(), glm::mat4(1.0f));
  if (skin.inverseBindMatrices < 0) return out;
  const AccessorRead r{model, source, "the skin's inverse bind matrices", {TINYGLTF_TYPE_MAT4}, {TINYGLTF_COMPONENT_TYPE_FLOAT}, skin.joints.size()};
  const auto n = readAccessor(r, skin.inverseBindMatrices, [&](std::uint64_t i, const auto& v) {
    for (int k = 0; k < 16; ++k) glm::value_ptr(out[i])[k] = float(v[std::size_t(k)]);
  });
  if (n != skin.joints.size()) throw Error(source + ": " + std::to_string(n) + " inverse bind matrices for " + std::to_string(skin.joints.size()) + " joints");
  return out;
}

// Per node the nearest node at or above it that is in `joints` (or -1), in one pass parents first.
std::vector<int> jointsAtOrAbove(const GltfScene& scene, const std::map<int, std::size_t>& joints) {
  std::vector<int> at(scene.parent.size(), -1);
  for (int n : scene.order) {
    const int p = scene.parent[std::size_t(n)];
    at[std::size_t(n)] = joints.count(n) ? n : (p >= 0 ? at[std::size_t(p)] : -1);
  }
  return at;
}
}  // namespace

GltfSkeleton gltfSkeleton(const tinygltf::Model& model, const GltfScene& scene, const std::string& source) {
  const tinygltf::Skin& skin = model.skins[std::size_t(scene.skin)];
  if (skin.joints.empty() || skin.joints.size() > kMaxMeshJoints)
    throw Error(source + ": the skin has " + std::to_string(skin.joints.size()) + " joints (1.." + std::to_string(kMaxMeshJoints) + " are read)");
  std::map<int, std::size_t> position;  // node -> position in skin.joints
  for (std::size_t i = 0; i < skin.joints.size(); ++i) {
    const int n = skin.joints[i];
    if (n < 0 || std::size_t(n) >= model.nodes.size() || !position.emplace(n, i).second)
      throw Error(source + ": skin joint " + std::to_string(i) + " is not a node or is named twice");
  }
  const std::vector<int> atOrAbove = jointsAtOrAbove(scene, position);
  const auto jointAncestor = [&](int node) {  // the nearest joint strictly above
    const int p = scene.parent[std::size_t(node)];
    return p >= 0 ? atOrAbove[std::size_t(p)] : -1;
  };
  // Parents first: order the joints by how many joint ancestors they have (then by position), counted parents first.
  std::vector<std::size_t> jointDepth(scene.parent.size(), 0);
  for (int n : scene.order)
    if (position.count(n)) {
      const int a = jointAncestor(n);
      jointDepth[std::size_t(n)] = a >= 0 ? jointDepth[std::size_t(a)] + 1 : 0;
    }
  std::vector<std::pair<std::size_t, std::size_t>> depth;  // (depth, position)
  for (std::size_t i = 0; i < skin.joints.size(); ++i) depth.emplace_back(jointDepth[std::size_t(skin.joints[i])], i);
  std::sort(depth.begin(), depth.end());  // (depth, position) pairs are distinct: the order is the stable one
  const std::vector<glm::mat4> ibm = inverseBinds(model, skin, source);
  GltfSkeleton out;
  out.jointAtOrAbove = atOrAbove;
  out.remap.resize(skin.joints.size());
  for (const auto& [d, i] : depth) {
    const int node = skin.joints[i];
    out.remap[i] = std::uint32_t(out.joints.size());
    out.ofNode[node] = std::uint32_t(out.joints.size());
    out.nodeOf.push_back(node);
    Joint j;
    j.name = model.nodes[std::size_t(node)].name.empty() ? "joint " + std::to_string(i) : model.nodes[std::size_t(node)].name;
    const int parentJoint = jointAncestor(node);
    j.parent = parentJoint >= 0 ? std::int32_t(out.ofNode.at(parentJoint)) : -1;
    const int parentNode = scene.parent[std::size_t(node)];
    // Between a joint and its joint parent there may be plain nodes: their rest transforms are kept.
    const glm::mat4 parentGlobal = parentNode >= 0 ? scene.global[std::size_t(parentNode)] : glm::mat4(1.0f);
    j.parentRest = parentJoint >= 0 ? glm::inverse(scene.global[std::size_t(parentJoint)]) * parentGlobal : parentGlobal;
    const JointPose rest = restOf(model.nodes[std::size_t(node)], source + ": " + nodeName(model, node));
    j.translation = rest.translation, j.rotation = rest.rotation, j.scale = rest.scale;
    j.inverseBind = ibm[i];
    out.joints.push_back(j);
  }
  return out;
}

std::int32_t rigidJointOf(GltfSkeleton& skeleton, const GltfScene&, int node) {
  const int joint = skeleton.jointAtOrAbove[std::size_t(node)];  // -1 keys the static joint
  if (const auto it = skeleton.ofNode.find(joint); it != skeleton.ofNode.end()) return std::int32_t(it->second);
  Joint still;
  still.name = "<static>";
  skeleton.ofNode[-1] = std::uint32_t(skeleton.joints.size());
  skeleton.nodeOf.push_back(-1);
  skeleton.joints.push_back(still);
  return std::int32_t(skeleton.joints.size() - 1);
}

namespace {
AnimationChannel readChannel(const tinygltf::Model& model, const tinygltf::Animation& anim, const tinygltf::AnimationChannel& c,
                             std::uint32_t joint, const std::string& what, std::uint64_t& keysLeft) {
  if (c.sampler < 0 || std::size_t(c.sampler) >= anim.samplers.size()) throw Error(what + " names no sampler");
  const tinygltf::AnimationSampler& s = anim.samplers[std::size_t(c.sampler)];
  // Every channel copies its keys (channels may share a sampler): the file's keys in all are bounded.
  const std::uint64_t keys = s.input >= 0 && std::size_t(s.input) < model.accessors.size() ? model.accessors[std::size_t(s.input)].count : 0;
  if (keys > keysLeft)
    throw Error(what + ": the file's animation channels hold more than " + std::to_string(kMaxAnimationKeys) + " keys in all");
  keysLeft -= keys;
  AnimationChannel ch;
  ch.joint = joint;
  ch.path = c.target_path == "translation" ? AnimationChannel::Path::Translation
            : c.target_path == "rotation" ? AnimationChannel::Path::Rotation : AnimationChannel::Path::Scale;
  const bool cubic = s.interpolation == "CUBICSPLINE";
  if (s.interpolation == "STEP") ch.interpolation = AnimationChannel::Interpolation::Step;
  else if (s.interpolation != "LINEAR" && !cubic) throw Error(what + " has interpolation '" + s.interpolation + "'");
  const std::string& source = what;  // messages below name the channel
  AccessorRead r{model, source, "key times", {TINYGLTF_TYPE_SCALAR}, {TINYGLTF_COMPONENT_TYPE_FLOAT}, kMaxAnimationKeys};
  readAccessor(r, s.input, [&](std::uint64_t, const auto& v) { ch.times.push_back(float(v[0])); });
  const bool rotation = ch.path == AnimationChannel::Path::Rotation;
  r.what = "key values", r.types = {rotation ? TINYGLTF_TYPE_VEC4 : TINYGLTF_TYPE_VEC3};
  r.maxCount = ch.times.size() * (cubic ? 3 : 1);
  const auto n = readAccessor(r, s.output, [&](std::uint64_t i, const auto& v) {
    if (!cubic || i % 3 == 1) ch.values.push_back(glm::vec4(float(v[0]), float(v[1]), float(v[2]), rotation ? float(v[3]) : 0.0f));
  });
  if (n != r.maxCount) throw Error(what + " has " + std::to_string(n) + " values for " + std::to_string(ch.times.size()) + " keys");
  return ch;
}
}  // namespace

std::vector<AnimationClip> gltfAnimations(const tinygltf::Model& model, const GltfSkeleton& skeleton, const std::string& source) {
  std::vector<AnimationClip> clips;
  std::uint64_t keysLeft = kMaxAnimationKeys;
  for (std::size_t a = 0; a < model.animations.size(); ++a) {
    const tinygltf::Animation& anim = model.animations[a];
    AnimationClip clip;
    clip.name = anim.name.empty() ? "animation " + std::to_string(a) : anim.name;
    for (std::size_t c = 0; c < anim.channels.size(); ++c) {
      const tinygltf::AnimationChannel& ch = anim.channels[c];
      const auto joint = skeleton.ofNode.find(ch.target_node);
      const bool pathRead = ch.target_path == "translation" || ch.target_path == "rotation" || ch.target_path == "scale";
      if (ch.target_node < 0 || joint == skeleton.ofNode.end() || !pathRead) continue;  // not a joint's transform
      const std::string what = source + ": animation '" + clip.name + "' channel " + std::to_string(c);
      clip.channels.push_back(readChannel(model, anim, ch, joint->second, what, keysLeft));
    }
    if (clip.channels.empty()) continue;
    if (clips.size() == kMaxClips) throw Error(source + ": more than " + std::to_string(kMaxClips) + " animation clips");
    clips.push_back(std::move(clip));
  }
  return clips;
}
}  // namespace hp
