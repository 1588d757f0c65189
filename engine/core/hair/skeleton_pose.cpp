#include "engine/core/hair/skeleton_pose.h"

#include <algorithm>
#include <cmath>

#include "engine/core/error.h"

namespace hp {
namespace {
// The channel's value at `t`: the keys around it blended (or the one before it for step keys).
glm::vec4 sampleChannel(const AnimationChannel& ch, float t) {
  const auto& times = ch.times;
  if (t <= times.front()) return ch.values.front();
  if (t >= times.back()) return ch.values.back();
  // times[k - 1] <= t < times[k]
  const std::size_t k = std::size_t(std::upper_bound(times.begin(), times.end(), t) - times.begin());
  const glm::vec4 a = ch.values[k - 1], b = ch.values[k];
  const float span = times[k] - times[k - 1];
  if (ch.interpolation == AnimationChannel::Interpolation::Step || !(span > 0.0f)) return a;
  const float f = (t - times[k - 1]) / span;
  if (ch.path != AnimationChannel::Path::Rotation) return glm::mix(a, b, f);
  const glm::quat qa(a.w, a.x, a.y, a.z), qb(b.w, b.x, b.y, b.z);
  const glm::quat q = glm::slerp(qa, glm::dot(qa, qb) < 0.0f ? -qb : qb, f);
  return {q.x, q.y, q.z, q.w};
}
}  // namespace

glm::mat4 jointMatrix(const JointPose& p) {
  glm::mat4 m = glm::mat4_cast(p.rotation);
  m[0] *= p.scale.x;
  m[1] *= p.scale.y;
  m[2] *= p.scale.z;
  m[3] = glm::vec4(p.translation, 1.0f);
  return m;
}

std::vector<JointPose> restPose(const CharacterMesh& mesh) {
  std::vector<JointPose> pose;
  pose.reserve(mesh.skeleton.size());
  for (const Joint& j : mesh.skeleton) pose.push_back({j.translation, j.rotation, j.scale});
  return pose;
}

const AnimationClip& findClip(const CharacterMesh& mesh, const std::string& name) {
  std::string names;
  for (const auto& clip : mesh.animations) {
    if (clip.name == name) return clip;
    names += (names.empty() ? "'" : ", '") + clip.name + "'";
  }
  throw Error(mesh.source + ": no animation '" + name + "' (" + (names.empty() ? "it has none" : "it has " + names) + ")");
}

std::vector<JointPose> samplePose(const CharacterMesh& mesh, const AnimationClip& clip, float seconds) {
  std::vector<JointPose> pose = restPose(mesh);
  const float t = std::clamp(std::isfinite(seconds) ? seconds : 0.0f, 0.0f, clip.duration);
  for (const auto& ch : clip.channels) {
    const glm::vec4 v = sampleChannel(ch, t);
    JointPose& p = pose[ch.joint];
    if (ch.path == AnimationChannel::Path::Translation) p.translation = glm::vec3(v);
    if (ch.path == AnimationChannel::Path::Scale) p.scale = glm::vec3(v);
    if (ch.path == AnimationChannel::Path::Rotation) p.rotation = glm::normalize(glm::quat(v.w, v.x, v.y, v.z));
  }
  return pose;
}

std::vector<glm::mat4> skinningMatrices(const CharacterMesh& mesh, std::span<const JointPose> pose) {
  if (pose.size() != mesh.skeleton.size())
    throw Error(mesh.source + ": a pose of " + std::to_string(pose.size()) + " joints for a skeleton of " +
                std::to_string(mesh.skeleton.size()));
  const glm::mat4 headToModel = glm::inverse(mesh.modelToHead);
  std::vector<glm::mat4> global(pose.size()), skin(pose.size());
  for (std::size_t j = 0; j < pose.size(); ++j) {
    const Joint& joint = mesh.skeleton[j];
    const glm::mat4 parent = (joint.parent >= 0 ? global[std::size_t(joint.parent)] : glm::mat4(1.0f)) * joint.parentRest;
    global[j] = parent * jointMatrix(pose[j]);
    skin[j] = mesh.modelToHead * global[j] * joint.inverseBind * headToModel;
  }
  return skin;
}

SkinnedVertices skinMesh(const CharacterMesh& mesh, std::span<const glm::mat4> matrices) {
  SkinnedVertices out{mesh.positions, mesh.normals};
  if (!mesh.skinned()) return out;
  if (matrices.size() != mesh.skeleton.size())
    throw Error(mesh.source + ": " + std::to_string(matrices.size()) + " skinning matrices for " +
                std::to_string(mesh.skeleton.size()) + " joints");
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    glm::mat4 m(0.0f);
    for (int k = 0; k < 4; ++k) m += mesh.weights[v][k] * matrices[mesh.joints[v][k]];
    out.positions[v] = glm::vec3(m * glm::vec4(mesh.positions[v], 1.0f));
    const glm::vec3 n = glm::transpose(glm::inverse(glm::mat3(m))) * mesh.normals[v];
    out.normals[v] = glm::length(n) > 0.0f ? glm::normalize(n) : mesh.normals[v];
  }
  return out;
}
}  // namespace hp
