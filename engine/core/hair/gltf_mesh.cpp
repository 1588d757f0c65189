// glTF 2.0 characters (docs/THEORY.md §8.5): tinygltf parses, this file walks the scene and checks.
#include "engine/core/hair/gltf_mesh.h"

#include <glm/gtc/type_ptr.hpp>
#include <glm/gtx/matrix_decompose.hpp>

#include <cstring>
#include <string_view>

#include "engine/core/error.h"
#include "engine/core/hair/gltf_accessor.h"
#include "engine/core/hair/gltf_skin.h"
#include "engine/core/hair/input_file.h"

namespace hp {
namespace {
constexpr std::uint64_t kMaxExternalBytes = 2ull << 30;  // all external buffers of one file together
constexpr std::size_t kMaxGltfJsonBytes = std::size_t(128) << 20;
constexpr int kMaxGltfJsonDepth = 64;

struct FileAccess {
  std::filesystem::path folder;  // empty: no file is read
  std::uint64_t bytesRead = 0;
};

bool fileExists(const std::string&, void* user) { return !static_cast<FileAccess*>(user)->folder.empty(); }
std::string expandPath(const std::string& path, void*) { return path; }
bool writeWholeFile(std::string* err, const std::string&, const std::vector<unsigned char>&, void*) {
  if (err) *err = "hairpipe writes no glTF files";
  return false;
}

// tinygltf joins the folder and the URI; the result must stay inside the folder.
bool readWholeFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* user) {
  try {
    auto& access = *static_cast<FileAccess*>(user);
    const std::filesystem::path p = std::filesystem::path(path).lexically_normal();
    const auto rel = p.lexically_relative(access.folder.lexically_normal());
    if (access.folder.empty() || rel.empty() || *rel.begin() == "..")
      throw Error("external file '" + excerpt(path) + "' is outside the glTF's folder (or the input is in memory)");
    const std::vector<std::byte> bytes = readInputBytes(p, kMaxMeshFileBytes);
    access.bytesRead += bytes.size();
    if (access.bytesRead > kMaxExternalBytes) throw Error("external buffers larger than 2 GiB in all");
    const auto* b = reinterpret_cast<const unsigned char*>(bytes.data());
    out->assign(b, b + bytes.size());
    return true;
  } catch (const std::exception& e) {
    if (err) *err += e.what();
    return false;
  }
}

bool ignoreImage(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) {
  return true;  // hairpipe reads geometry only
}

// The JSON of a .gltf (all of it) or a .glb (its first chunk, when the header holds one).
std::string_view jsonPart(std::span<const std::byte> bytes, bool binary) {
  const std::string_view all(reinterpret_cast<const char*>(bytes.data()), bytes.size());
  if (!binary) return all;
  if (bytes.size() < 20) return {};
  std::uint32_t length = 0;
  std::memcpy(&length, bytes.data() + 12, 4);
  return all.substr(20, std::min<std::size_t>(length, bytes.size() - 20));
}

// tinygltf parses nested JSON values recursively without a limit (extras, extensions): refuse deep nesting
// and very large JSON before it does (nlohmann's tree costs many times the text).
void checkJson(std::string_view json, const std::string& source) {
  if (json.size() > kMaxGltfJsonBytes)
    throw Error(source + ": its JSON is " + std::to_string(json.size()) + " bytes, more than " +
                std::to_string(kMaxGltfJsonBytes) + " (keep buffers in a .bin or a .glb)");
  int depth = 0;
  bool inString = false;
  for (std::size_t i = 0; i < json.size(); ++i) {
    const char c = json[i];
    if (inString) {
      if (c == '\\') ++i;
      else if (c == '"') inString = false;
    } else if (c == '"') {
      inString = true;
    } else if (c == '{' || c == '[') {
      if (++depth > kMaxGltfJsonDepth)
        throw Error(source + ": its JSON nests deeper than " + std::to_string(kMaxGltfJsonDepth) + " levels");
    } else if (c == '}' || c == ']') {
      --depth;
    }
  }
}

tinygltf::Model parseModel(std::span<const std::byte> bytes, const std::string& source, FileAccess& access) {
  if (bytes.size() > kMaxMeshFileBytes) throw Error(source + ": larger than hairpipe reads");
  checkJson(jsonPart(bytes, bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0), source);
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(&ignoreImage, nullptr);
  loader.SetFsCallbacks({&fileExists, &expandPath, &readWholeFile, &writeWholeFile, &access});
  tinygltf::Model model;
  std::string err, warn;
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  const bool binary = bytes.size() >= 4 && std::memcmp(data, "glTF", 4) == 0;
  const std::string folder = access.folder.string();
  const auto size = static_cast<unsigned int>(bytes.size());
  const bool ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, data, size, folder)
                         : loader.LoadASCIIFromString(&model, &err, &warn, reinterpret_cast<const char*>(data), size, folder);
  if (!ok) throw Error(source + ": not a glTF hairpipe can read: " + excerpt(err.empty() ? warn : err, 300));
  return model;
}

glm::vec3 pointOf(const std::array<double, 16>& v) { return {float(v[0]), float(v[1]), float(v[2])}; }

// Triangles of a primitive's index list by its mode (4 list, 5 strip, 6 fan), refused before past kMaxMeshTriangles.
void appendTriangles(int mode, const std::vector<std::uint32_t>& idx, std::uint32_t base, std::vector<glm::uvec3>& out,
                     const std::string& what) {
  const std::size_t n = idx.size();
  const std::size_t adding = mode == 4 ? n / 3 : (n > 2 ? n - 2 : 0);
  if (out.size() + adding > kMaxMeshTriangles)
    throw Error(what + " would take the mesh past " + std::to_string(kMaxMeshTriangles) + " triangles");
  if (mode == 4)
    for (std::size_t i = 0; i + 2 < n; i += 3) out.push_back(glm::uvec3(idx[i], idx[i + 1], idx[i + 2]) + base);
  if (mode == 5)
    for (std::size_t i = 2; i < n; ++i)
      out.push_back(glm::uvec3(idx[i - 2], i % 2 ? idx[i] : idx[i - 1], i % 2 ? idx[i - 1] : idx[i]) + base);
  if (mode == 6)
    for (std::size_t i = 2; i < n; ++i) out.push_back(glm::uvec3(idx[0], idx[i - 1], idx[i]) + base);
}

// How a primitive's vertices are weighted: its own JOINTS_0/WEIGHTS_0 (remapped), one joint, or none.
struct PrimitiveSkin {
  const std::vector<std::uint32_t>* remap = nullptr;  // skinned: file joint index -> skeleton index
  std::int32_t rigidJoint = -1;                       // rigid in a skinned file: the joint it follows
};

void readSkinAttributes(const AccessorRead& base, const tinygltf::Primitive& p, std::size_t first,
                        const std::vector<std::uint32_t>& remap, CharacterMesh& m) {
  const auto joints = p.attributes.find("JOINTS_0"), weights = p.attributes.find("WEIGHTS_0");
  if (joints == p.attributes.end() || weights == p.attributes.end())
    throw Error(base.source + ": " + base.what + " is skinned but has no JOINTS_0 and WEIGHTS_0");
  const std::size_t count = m.positions.size() - first;
  m.joints.resize(m.positions.size());
  m.weights.resize(m.positions.size());
  AccessorRead r = base;
  r.what = base.what + " JOINTS_0", r.types = {TINYGLTF_TYPE_VEC4}, r.maxCount = count;
  r.components = {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT};
  const auto nj = readAccessor(r, joints->second, [&](std::uint64_t i, const auto& v) {
    for (int k = 0; k < 4; ++k) {
      const auto j = std::size_t(v[std::size_t(k)]);
      m.joints[first + i][k] = j < remap.size() ? remap[j] : std::uint32_t(kMaxMeshJoints);  // past: finish refuses if weighted
    }
  });
  r.what = base.what + " WEIGHTS_0";
  r.components = {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT};
  const auto nw = readAccessor(r, weights->second, [&](std::uint64_t i, const auto& v) {
    m.weights[first + i] = glm::vec4(float(v[0]), float(v[1]), float(v[2]), float(v[3]));
  });
  if (nj != count || nw != count) throw Error(base.source + ": " + base.what + " has joints or weights for other than its " + std::to_string(count) + " vertices");
}

// A rigid primitive's vertices: placed by its node's rest transform, and in a skinned file moved into the bind
// space of the joint it follows (so that joint's bind pose puts them back where its rest pose has them).
glm::mat4 rigidToBind(const GltfScene& scene, const GltfSkeleton& skeleton, std::int32_t joint, int node) {
  const glm::mat4& placed = scene.global[std::size_t(node)];
  if (joint < 0 || skeleton.nodeOf[std::size_t(joint)] < 0) return placed;
  const glm::mat4& jointRest = scene.global[std::size_t(skeleton.nodeOf[std::size_t(joint)])];
  return glm::inverse(skeleton.joints[std::size_t(joint)].inverseBind) * glm::inverse(jointRest) * placed;
}

void appendPrimitive(const AccessorRead& base, const tinygltf::Primitive& p, const glm::mat4& toModel,
                     const PrimitiveSkin& skin, CharacterMesh& m) {
  const auto pos = p.attributes.find("POSITION");
  if (pos == p.attributes.end()) throw Error(base.source + ": " + base.what + " has no POSITION");
  const std::size_t first = m.positions.size();
  AccessorRead r = base;
  r.what = base.what + " POSITION", r.types = {TINYGLTF_TYPE_VEC3}, r.components = {TINYGLTF_COMPONENT_TYPE_FLOAT};
  r.maxCount = kMaxMeshVertices - first;
  const auto count = readAccessor(r, pos->second, [&](std::uint64_t, const auto& v) {
    m.positions.push_back(glm::vec3(toModel * glm::vec4(pointOf(v), 1.0f)));
  });
  const auto nrm = p.attributes.find("NORMAL");
  const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(toModel)));
  m.normals.resize(m.positions.size(), glm::vec3(0.0f));  // zero: computed from the triangles
  if (nrm != p.attributes.end()) {
    r.what = base.what + " NORMAL", r.maxCount = count;
    readAccessor(r, nrm->second, [&](std::uint64_t i, const auto& v) { m.normals[first + i] = normalMatrix * pointOf(v); });
  }
  if (skin.remap) readSkinAttributes(base, p, first, *skin.remap, m);
  if (skin.rigidJoint >= 0) {
    m.joints.resize(m.positions.size(), glm::uvec4(std::uint32_t(skin.rigidJoint), 0, 0, 0));
    m.weights.resize(m.positions.size(), glm::vec4(1, 0, 0, 0));
  }
  std::vector<std::uint32_t> idx;
  if (p.indices >= 0) {
    r.what = base.what + " indices", r.types = {TINYGLTF_TYPE_SCALAR}, r.maxCount = 3 * (kMaxMeshTriangles - m.triangles.size());
    r.components = {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT};
    readAccessor(r, p.indices, [&](std::uint64_t, const auto& v) {
      if (v[0] >= double(count)) throw Error(base.source + ": " + base.what + " index " + std::to_string(std::uint64_t(v[0])) + " is past its " + std::to_string(count) + " vertices");
      idx.push_back(std::uint32_t(v[0]));
    });
  } else {
    for (std::uint32_t i = 0; i < count; ++i) idx.push_back(i);
  }
  appendTriangles(p.mode < 0 ? 4 : p.mode, idx, std::uint32_t(first), m.triangles, base.source + ": " + base.what);
}
}  // namespace

CharacterMesh parseGltf(std::span<const std::byte> bytes, const std::string& source, const std::filesystem::path& folder,
                        const ModelTransform& transform) {
  transform.validate();
  FileAccess access{folder};
  const tinygltf::Model model = parseModel(bytes, source, access);
  const GltfScene scene = gltfScene(model, source);
  CharacterMesh m;
  m.source = source;
  GltfSkeleton skeleton;
  if (scene.skin >= 0) skeleton = gltfSkeleton(model, scene, source);
  for (const auto& [node, meshIndex] : scene.instances) {
    const tinygltf::Mesh& mesh = model.meshes[std::size_t(meshIndex)];
    const bool skinned = model.nodes[std::size_t(node)].skin >= 0;
    PrimitiveSkin skin;
    if (skinned) skin.remap = &skeleton.remap;
    if (!skinned && scene.skin >= 0) skin.rigidJoint = rigidJointOf(skeleton, scene, node);
    const glm::mat4 toModel = skinned ? glm::mat4(1.0f) : rigidToBind(scene, skeleton, skin.rigidJoint, node);
    for (std::size_t p = 0; p < mesh.primitives.size(); ++p) {
      const int mode = mesh.primitives[p].mode;
      if (mode >= 0 && mode < 4) continue;  // points and lines
      if (mode > 6) throw Error(source + ": mesh " + std::to_string(meshIndex) + " primitive " + std::to_string(p) + " has mode " + std::to_string(mode));
      const AccessorRead base{model, source, "mesh " + std::to_string(meshIndex) + " primitive " + std::to_string(p), {}, {}, 0};
      appendPrimitive(base, mesh.primitives[p], toModel, skin, m);
      if (m.triangles.size() > kMaxMeshTriangles) throw Error(source + ": more than " + std::to_string(kMaxMeshTriangles) + " triangles");
    }
  }
  m.skeleton = std::move(skeleton.joints);
  m.animations = gltfAnimations(model, skeleton, source);
  for (auto& p : m.positions) p = transform.applyToPoint(p);
  for (auto& n : m.normals) n = transform.applyToNormal(n);
  m.modelToHead = transform.matrix();
  finishCharacterMesh(m);
  return m;
}

CharacterMesh readGltfFile(const std::filesystem::path& path, const ModelTransform& transform) {
  const std::vector<std::byte> bytes = readInputBytes(path, kMaxMeshFileBytes);
  std::filesystem::path folder = path.parent_path();
  if (folder.empty()) folder = ".";
  return parseGltf(bytes, path.string(), folder, transform);
}
}  // namespace hp
