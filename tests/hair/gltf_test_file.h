#pragma once
// Test support: small glTF 2.0 binaries (.glb) written from plain arrays, so the tests make their own
// characters: one mesh (positions, normals, indices), optionally skinned by a chain of joints (translation
// only at rest, inverse binds the rest globals' inverses) and animated by rotation keys on one joint.
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace hp::test {
struct GltfJoint {
  std::string name;
  int parent = -1;  // an earlier joint, or -1
  glm::vec3 translation{0.0f};
};

struct GltfRotationClip {
  std::string name;
  int joint = 0;
  std::vector<float> times;
  std::vector<glm::quat> rotations;
};

struct GltfTestMesh {
  std::vector<glm::vec3> positions, normals;
  std::vector<std::uint32_t> indices;
  std::vector<GltfJoint> joints;           // empty: a rigid mesh
  std::vector<glm::u16vec4> vertexJoints;  // per vertex when skinned
  std::vector<glm::vec4> vertexWeights;
  std::vector<GltfRotationClip> clips;
};

namespace gltf_detail {
struct Writer {
  std::vector<std::byte> bin;
  nlohmann::json views = nlohmann::json::array(), accessors = nlohmann::json::array();
  // Appends the bytes as a view and an accessor; returns the accessor's index.
  template <typename T>
  int add(const std::vector<T>& data, int componentType, const char* type, std::size_t count) {
    while (bin.size() % 4) bin.push_back(std::byte{0});
    const std::size_t offset = bin.size(), bytes = data.size() * sizeof(T);
    bin.resize(offset + bytes);
    if (bytes) std::memcpy(bin.data() + offset, data.data(), bytes);
    views.push_back({{"buffer", 0}, {"byteOffset", offset}, {"byteLength", bytes}});
    accessors.push_back({{"bufferView", views.size() - 1}, {"componentType", componentType}, {"count", count}, {"type", type}});
    return int(accessors.size() - 1);
  }
};

inline void appendChunk(std::vector<std::byte>& out, const std::vector<std::byte>& data, std::uint32_t type, std::byte pad) {
  std::vector<std::byte> padded = data;
  while (padded.size() % 4) padded.push_back(pad);
  const std::uint32_t header[2] = {std::uint32_t(padded.size()), type};
  const auto* h = reinterpret_cast<const std::byte*>(header);
  out.insert(out.end(), h, h + 8);
  out.insert(out.end(), padded.begin(), padded.end());
}
}  // namespace gltf_detail

inline std::vector<std::byte> glbBytes(const GltfTestMesh& m) {
  gltf_detail::Writer w;
  nlohmann::json attributes = {{"POSITION", w.add(m.positions, 5126, "VEC3", m.positions.size())}};
  if (!m.normals.empty()) attributes["NORMAL"] = w.add(m.normals, 5126, "VEC3", m.normals.size());
  if (!m.joints.empty()) {
    attributes["JOINTS_0"] = w.add(m.vertexJoints, 5123, "VEC4", m.vertexJoints.size());
    attributes["WEIGHTS_0"] = w.add(m.vertexWeights, 5126, "VEC4", m.vertexWeights.size());
  }
  const int indices = w.add(m.indices, 5125, "SCALAR", m.indices.size());
  nlohmann::json gltf = {{"asset", {{"version", "2.0"}}}, {"scene", 0}};
  gltf["meshes"] = {{{"primitives", {{{"attributes", attributes}, {"indices", indices}}}}}};
  nlohmann::json nodes = {{{"mesh", 0}, {"name", "body"}}};
  nlohmann::json rootNodes = {0};
  if (!m.joints.empty()) {
    nodes[0]["skin"] = 0;
    std::vector<glm::mat4> inverseBinds;
    std::vector<glm::vec3> global;
    nlohmann::json jointNodes = nlohmann::json::array();
    for (std::size_t j = 0; j < m.joints.size(); ++j) {
      const GltfJoint& joint = m.joints[j];
      global.push_back((joint.parent >= 0 ? global[std::size_t(joint.parent)] : glm::vec3(0.0f)) + joint.translation);
      glm::mat4 inv(1.0f);
      inv[3] = glm::vec4(-global.back(), 1.0f);
      inverseBinds.push_back(inv);
      nodes.push_back({{"name", joint.name}, {"translation", {joint.translation.x, joint.translation.y, joint.translation.z}}});
      jointNodes.push_back(nodes.size() - 1);
      if (joint.parent >= 0) nodes[1 + std::size_t(joint.parent)]["children"].push_back(nodes.size() - 1);
      else rootNodes.push_back(nodes.size() - 1);
    }
    gltf["skins"] = {{{"joints", jointNodes}, {"inverseBindMatrices", w.add(inverseBinds, 5126, "MAT4", inverseBinds.size())}}};
  }
  nlohmann::json animations = nlohmann::json::array();
  for (const GltfRotationClip& c : m.clips) {
    std::vector<glm::vec4> values;
    for (const glm::quat& q : c.rotations) values.emplace_back(q.x, q.y, q.z, q.w);
    const int input = w.add(c.times, 5126, "SCALAR", c.times.size()), output = w.add(values, 5126, "VEC4", values.size());
    animations.push_back({{"name", c.name},
                          {"samplers", {{{"input", input}, {"output", output}, {"interpolation", "LINEAR"}}}},
                          {"channels", {{{"sampler", 0}, {"target", {{"node", 1 + c.joint}, {"path", "rotation"}}}}}}});
  }
  if (!animations.empty()) gltf["animations"] = animations;
  gltf["nodes"] = nodes;
  gltf["scenes"] = {{{"nodes", rootNodes}}};
  gltf["bufferViews"] = w.views;
  gltf["accessors"] = w.accessors;
  gltf["buffers"] = {{{"byteLength", w.bin.size()}}};
  const std::string json = gltf.dump();
  std::vector<std::byte> jsonBytes(reinterpret_cast<const std::byte*>(json.data()),
                                   reinterpret_cast<const std::byte*>(json.data()) + json.size());
  std::vector<std::byte> body;
  gltf_detail::appendChunk(body, jsonBytes, 0x4E4F534Au, std::byte{' '});
  gltf_detail::appendChunk(body, w.bin, 0x004E4942u, std::byte{0});
  const std::uint32_t header[3] = {0x46546C67u, 2u, std::uint32_t(12 + body.size())};
  std::vector<std::byte> out(reinterpret_cast<const std::byte*>(header), reinterpret_cast<const std::byte*>(header) + 12);
  out.insert(out.end(), body.begin(), body.end());
  return out;
}

// A UV sphere of `radius` (slices x stacks quads, poles fanned), outward normals, counter-clockwise from outside.
inline GltfTestMesh uvSphere(float radius, int slices = 32, int stacks = 16) {
  GltfTestMesh m;
  for (int i = 0; i <= stacks; ++i)
    for (int j = 0; j <= slices; ++j) {
      const float theta = 3.14159265f * float(i) / float(stacks), phi = 6.2831853f * float(j) / float(slices);
      const glm::vec3 n(std::sin(theta) * std::sin(phi), std::cos(theta), std::sin(theta) * std::cos(phi));
      m.positions.push_back(radius * n);
      m.normals.push_back(n);
    }
  const auto at = [slices](int i, int j) { return std::uint32_t(i * (slices + 1) + j); };
  for (int i = 0; i < stacks; ++i)
    for (int j = 0; j < slices; ++j) {
      if (i > 0) m.indices.insert(m.indices.end(), {at(i, j), at(i + 1, j), at(i, j + 1)});
      if (i + 1 < stacks) m.indices.insert(m.indices.end(), {at(i, j + 1), at(i + 1, j), at(i + 1, j + 1)});
    }
  return m;
}
}  // namespace hp::test
