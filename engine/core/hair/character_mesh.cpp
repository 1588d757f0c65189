#include "engine/core/hair/character_mesh.h"

#include <algorithm>
#include <cmath>

#include "engine/core/error.h"
#include "engine/core/hair/finite.h"
#include "engine/core/hair/model_transform.h"
#include "engine/core/hair/scalp_mesh.h"

namespace hp {
namespace {
bool finite3(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
bool finite4(const glm::vec4& v) { return finite3(glm::vec3(v)) && std::isfinite(v.w); }

void checkGeometry(const CharacterMesh& m) {
  const std::string& s = m.source;
  checkMeshVertices(m.positions, s);
  checkMeshIndices(m.triangles, m.positions.size(), s);
  if (!m.normals.empty() && m.normals.size() != m.positions.size())
    throw Error(s + ": " + std::to_string(m.normals.size()) + " normals for " + std::to_string(m.positions.size()) +
                " vertices");
}

// v at unit length, or zero for a zero or non-finite v. Scaled by its largest component first, so tiny
// (subnormal) and huge vectors normalise as well as any.
glm::vec3 unitOrZero(const glm::vec3& v) {
  if (!finite3(v)) return glm::vec3(0.0f);
  const float largest = std::max(std::abs(v.x), std::max(std::abs(v.y), std::abs(v.z)));
  if (!(largest > 0.0f) || !std::isfinite(largest)) return glm::vec3(0.0f);
  const glm::vec3 scaled = v / largest;
  return scaled / glm::length(scaled);
}

// Given normals are normalised; a vertex without a usable one takes the area-weighted normal of its
// triangles (and a vertex in no triangle +Y: it is never drawn).
void finishNormals(CharacterMesh& m) {
  std::vector<glm::vec3> computed(m.positions.size(), glm::vec3(0.0f));
  for (const auto& t : m.triangles) {
    const glm::vec3 n = triangleAreaVector(m.positions, t);
    for (int k = 0; k < 3; ++k) computed[t[k]] += n;
  }
  if (m.normals.empty()) m.normals.assign(m.positions.size(), glm::vec3(0.0f));
  for (std::size_t i = 0; i < m.normals.size(); ++i) {
    const glm::vec3 given = unitOrZero(m.normals[i]);
    const glm::vec3 n = given != glm::vec3(0.0f) ? given : unitOrZero(computed[i]);
    m.normals[i] = n != glm::vec3(0.0f) ? n : glm::vec3(0.0f, 1.0f, 0.0f);
  }
}

void checkSkin(CharacterMesh& m) {
  const std::string& s = m.source;
  if (m.joints.size() != m.weights.size() || (!m.weights.empty() && m.weights.size() != m.positions.size()))
    throw Error(s + ": " + std::to_string(m.joints.size()) + " joint sets and " + std::to_string(m.weights.size()) +
                " weight sets for " + std::to_string(m.positions.size()) + " vertices");
  if (m.skeleton.size() > kMaxMeshJoints)
    throw Error(s + ": " + std::to_string(m.skeleton.size()) + " joints, more than " + std::to_string(kMaxMeshJoints));
  if (m.skinned() && m.skeleton.empty()) throw Error(s + ": skin weights without a skeleton");
  for (std::size_t v = 0; v < m.weights.size(); ++v) {
    glm::vec4& w = m.weights[v];
    const std::string what = s + ": vertex " + std::to_string(v) + "'s ";
    if (!finite4(w) || w.x < 0 || w.y < 0 || w.z < 0 || w.w < 0) throw Error(what + "weights are negative or not finite");
    const float largest = std::max(std::max(w.x, w.y), std::max(w.z, w.w));
    if (!(largest > 0.0f)) throw Error(what + "weights sum to 0");
    w /= largest;  // first, so that huge weights cannot sum to infinity
    w /= w.x + w.y + w.z + w.w;
    for (int k = 0; k < 4; ++k)
      if (m.joints[v][k] >= m.skeleton.size()) {
        if (w[k] > 0.0f)
          throw Error(what + "joint " + std::to_string(m.joints[v][k]) + " is past the skeleton's " +
                      std::to_string(m.skeleton.size()));
        m.joints[v][k] = 0;  // an unused slot
      }
  }
}

void checkSkeleton(const CharacterMesh& m) {
  for (std::size_t j = 0; j < m.skeleton.size(); ++j) {
    const Joint& joint = m.skeleton[j];
    const std::string what = m.source + ": joint " + std::to_string(j) + " (" + joint.name + ")";
    if (joint.parent >= std::int32_t(j)) throw Error(what + " comes before its parent");
    if (joint.parent < -1) throw Error(what + " has parent " + std::to_string(joint.parent));
    if (!allFinite(joint.inverseBind) || !allFinite(joint.parentRest) || !finite3(joint.translation) ||
        !finite3(joint.scale) || !finite4(glm::vec4(joint.rotation.x, joint.rotation.y, joint.rotation.z, joint.rotation.w)))
      throw Error(what + " has a transform that is not finite");
  }
}

void checkAnimations(CharacterMesh& m) {
  for (auto& clip : m.animations) {
    clip.duration = 0.0f;
    for (std::size_t c = 0; c < clip.channels.size(); ++c) {
      AnimationChannel& ch = clip.channels[c];
      const std::string what = m.source + ": animation '" + clip.name + "' channel " + std::to_string(c);
      if (ch.joint >= m.skeleton.size()) throw Error(what + " drives joint " + std::to_string(ch.joint) + ", past the skeleton");
      if (ch.times.empty() || ch.times.size() != ch.values.size())
        throw Error(what + " has " + std::to_string(ch.times.size()) + " key times and " +
                    std::to_string(ch.values.size()) + " values");
      for (std::size_t k = 0; k < ch.times.size(); ++k) {
        if (!std::isfinite(ch.times[k]) || ch.times[k] < 0.0f || (k > 0 && ch.times[k] < ch.times[k - 1]))
          throw Error(what + ": key " + std::to_string(k) + "'s time is negative, not finite or before the key before it");
        if (!finite4(ch.values[k])) throw Error(what + ": key " + std::to_string(k) + "'s value is not finite");
        if (ch.path == AnimationChannel::Path::Rotation) {
          glm::vec4& q = ch.values[k];
          const float largest = std::max(std::max(std::abs(q.x), std::abs(q.y)), std::max(std::abs(q.z), std::abs(q.w)));
          if (!(largest > 1e-6f)) throw Error(what + ": key " + std::to_string(k) + " is a zero quaternion");
          q /= largest;  // first, so that a huge one cannot have an infinite length
          q /= glm::length(q);
        }
      }
      clip.duration = std::max(clip.duration, ch.times.back());
    }
  }
}
}  // namespace

void finishCharacterMesh(CharacterMesh& mesh) {
  if (mesh.positions.size() > kMaxMeshVertices || mesh.triangles.size() > kMaxMeshTriangles)
    throw Error(mesh.source + ": " + std::to_string(mesh.positions.size()) + " vertices and " +
                std::to_string(mesh.triangles.size()) + " triangles, more than hairpipe reads");
  checkGeometry(mesh);
  checkHeadSpaceExtent(mesh.positions, mesh.source);  // before the degenerate test squares their distances
  mesh.droppedDegenerateTriangles += dropDegenerateTriangles(mesh.positions, mesh.triangles);
  if (mesh.triangles.empty()) throw Error(mesh.source + ": no non-degenerate triangles");
  finishNormals(mesh);
  checkSkeleton(mesh);
  checkSkin(mesh);
  checkAnimations(mesh);
}
}  // namespace hp
