#include "compute/strands/character_pass.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "engine/core/error.h"
#include "engine/core/hair/finite.h"
#include "engine/vk/barriers.h"
#include "engine/vk/context.h"
#include "engine/vk/transfer.h"

namespace hp {
namespace {
const vk::Binding kCharacterBindings[] = {
    {gpu::CHARACTER_BINDING_REST, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, vk::kCompute},
    {gpu::CHARACTER_BINDING_SKIN, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, vk::kCompute},
    {gpu::CHARACTER_BINDING_BONES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, vk::kCompute},
    {gpu::CHARACTER_BINDING_POSED, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, vk::kCompute},
    {gpu::CHARACTER_BINDING_POSED_NORMALS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, vk::kCompute},
    {gpu::CHARACTER_BINDING_TRIANGLES, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, vk::kCompute},
    {gpu::CHARACTER_BINDING_KEYS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, vk::kCompute},
    {gpu::CHARACTER_BINDING_SDF, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, vk::kCompute},
};
constexpr VkBufferUsageFlags kCharacterUsage =
    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;

template <typename T>
vk::Buffer uploaded(const vk::Context& ctx, const std::vector<T>& data, const char* name) {
  const VkDeviceSize bytes = data.size() * sizeof(T);
  if (bytes > ctx.properties().limits.maxStorageBufferRange)
    throw Error(std::string("character mesh: its ") + name + " take " + std::to_string(bytes) +
                " bytes, past this device's maxStorageBufferRange");
  vk::Buffer b(ctx, bytes, kCharacterUsage, vk::MemoryKind::DeviceLocal, std::string("character ") + name);
  vk::upload<T>(ctx, b, data, vk::BufferUse::ComputeRead);
  return b;
}

// The z slices of a posed triangle's box: its longest edge (as long in any pose of a skinning that does not
// stretch it) and the band on either side, in cells. One slice (the splat invocation's loop) must stay within
// CHARACTER_MAX_SLICE_NODES nodes, or the mesh's triangles are too large for the grid's cells.
std::uint32_t slicesPerTriangle(const CharacterMesh& mesh, float cell) {
  float longest = 0.0f;
  for (const glm::uvec3& t : mesh.triangles) {
    const glm::vec3 a = mesh.positions[t.x], b = mesh.positions[t.y], c = mesh.positions[t.z];
    longest = std::max({longest, glm::distance(a, b), glm::distance(b, c), glm::distance(c, a)});
  }
  const double cells = std::ceil(double(longest) / double(cell)) + 2.0 * gpu::CHARACTER_SDF_BAND_CELLS + 2.0;
  if (!(cells * cells <= double(gpu::CHARACTER_MAX_SLICE_NODES)))
    throw Error(mesh.source + ": a triangle " + std::to_string(longest) + " long spans " + std::to_string(cells) +
                " cells of its distance grid (" + std::to_string(cell) + "); a larger cell is needed");
  return std::uint32_t(cells);
}

std::vector<glm::vec4> restVertices(const CharacterMesh& mesh, std::span<const float> scalp) {
  std::vector<glm::vec4> out;
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    out.emplace_back(mesh.positions[v], 1.0f);
    out.emplace_back(mesh.normals[v], scalp.empty() ? 0.0f : scalp[v]);
  }
  return out;
}

std::vector<gpu::CharacterSkin> skinOf(const CharacterMesh& mesh) {
  std::vector<gpu::CharacterSkin> out;
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) out.push_back({mesh.joints[v], mesh.weights[v]});
  return out;
}
}  // namespace

CharacterPass::CharacterPass(const vk::Context& ctx, const CharacterMesh& mesh, std::span<const float> scalp,
                             const SdfBuffer& sdf, vk::PipelineLibrary* library)
    : ctx_(ctx), sdf_(sdf.buffer()) {
  if (!mesh.skinned()) throw Error(mesh.source + ": a character pass needs a skinned mesh");
  if (mesh.skeleton.size() > gpu::CHARACTER_MAX_BONES)
    throw Error(mesh.source + ": " + std::to_string(mesh.skeleton.size()) + " bones, more than " +
                std::to_string(gpu::CHARACTER_MAX_BONES));
  if (!sdf.grid() || sdf.grid()->empty()) throw Error(mesh.source + ": the character has no distance grid to rebuild");
  if (!scalp.empty() && scalp.size() != mesh.positions.size()) throw Error(mesh.source + ": one scalp weight per vertex is required");
  const SdfGrid& grid = *sdf.grid();
  params_.originCell = glm::vec4(grid.origin, grid.cell);
  params_.dims = glm::uvec4(grid.dims, std::uint32_t(grid.values.size()));
  params_.counts = glm::uvec4(mesh.vertexCount(), mesh.triangleCount(), gpu::CHARACTER_SDF_BAND_CELLS,
                              slicesPerTriangle(mesh, grid.cell));
  if (std::uint64_t(params_.counts.y) * params_.counts.w > (std::uint64_t(1) << 31))
    throw Error(mesh.source + ": " + std::to_string(params_.counts.y) + " triangles of " + std::to_string(params_.counts.w) +
                " grid slices each are more than one dispatch holds; a larger cell is needed");
  const std::vector<glm::vec4> rest = restVertices(mesh, scalp);
  rest_ = uploaded(ctx, rest, "rest vertices");
  skin_ = uploaded(ctx, skinOf(mesh), "skin weights");
  std::vector<glm::uvec4> tris;
  for (const auto& t : mesh.triangles) tris.emplace_back(t, 0u);
  triangles_ = uploaded(ctx, tris, "triangles");
  bones_.assign(mesh.skeleton.size(), glm::mat4(1.0f));
  bonesBuffer_ = uploaded(ctx, bones_, "bone matrices");
  std::vector<glm::vec4> positions, normals;
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) positions.push_back(rest[2 * v]), normals.push_back(rest[2 * v + 1]);
  posed_ = uploaded(ctx, positions, "posed positions");
  posedNormals_ = uploaded(ctx, normals, "posed normals");
  keys_ = uploaded(ctx, std::vector<std::uint32_t>(grid.values.size(), ~0u), "grid keys");
  set_ = vk::DescriptorSet(ctx, kCharacterBindings, "character");
  set_.writeStorageBuffer(gpu::CHARACTER_BINDING_REST, rest_.handle());
  set_.writeStorageBuffer(gpu::CHARACTER_BINDING_SKIN, skin_.handle());
  set_.writeStorageBuffer(gpu::CHARACTER_BINDING_BONES, bonesBuffer_.handle());
  set_.writeStorageBuffer(gpu::CHARACTER_BINDING_POSED, posed_.handle());
  set_.writeStorageBuffer(gpu::CHARACTER_BINDING_POSED_NORMALS, posedNormals_.handle());
  set_.writeStorageBuffer(gpu::CHARACTER_BINDING_TRIANGLES, triangles_.handle());
  set_.writeStorageBuffer(gpu::CHARACTER_BINDING_KEYS, keys_.handle());
  set_.writeStorageBuffer(gpu::CHARACTER_BINDING_SDF, sdf_.handle());
  const std::vector<VkDescriptorSetLayout> layouts{set_.layout()};
  const auto push = std::uint32_t(sizeof(gpu::CharacterParams));
  skinPipeline_ = vk::makeComputePipeline(ctx, library, "character_skin.comp", gpu::CHARACTER_WORKGROUP_SIZE, layouts, push, "character skin");
  splat_ = vk::makeComputePipeline(ctx, library, "character_sdf_splat.comp", gpu::CHARACTER_WORKGROUP_SIZE, layouts, push, "character grid splat");
  finish_ = vk::makeComputePipeline(ctx, library, "character_sdf_finish.comp", gpu::CHARACTER_WORKGROUP_SIZE, layouts, push, "character grid finish");
}

void CharacterPass::setPose(std::span<const glm::mat4> bones) {
  if (bones.size() != bones_.size())
    throw Error("character pose: " + std::to_string(bones.size()) + " bone matrices for a skeleton of " + std::to_string(bones_.size()));
  for (std::size_t b = 0; b < bones.size(); ++b)
    if (!allFinite(bones[b])) throw Error("character pose: bone " + std::to_string(b) + "'s matrix is not finite");
  bones_.assign(bones.begin(), bones.end());
  pending_ = true;
}

bool CharacterPass::record(VkCommandBuffer cmd) {
  if (!pending_) return false;
  pending_ = false;
  const auto& fn = ctx_.fn();
  // The last frame's reads of the bones, keys, posed vertices and grid come before this frame's writes.
  vk::memoryBarrier(ctx_, cmd, vk::BufferUse::ComputeWrite, vk::BufferUse::TransferDst);
  vk::memoryBarrier(ctx_, cmd, vk::BufferUse::TransferSrc, vk::BufferUse::TransferDst);
  fn.vkCmdUpdateBuffer(cmd, bonesBuffer_.handle(), 0, bones_.size() * sizeof(glm::mat4), bones_.data());
  fn.vkCmdFillBuffer(cmd, keys_.handle(), 0, VK_WHOLE_SIZE, ~0u);
  vk::memoryBarrier(ctx_, cmd, vk::BufferUse::TransferDst, vk::BufferUse::ComputeWrite);
  skinPipeline_->bind(cmd, set_.set());
  skinPipeline_->push(cmd, params_);
  skinPipeline_->dispatch(cmd, params_.counts.x);
  vk::memoryBarrier(ctx_, cmd, vk::BufferUse::ComputeWrite, vk::BufferUse::ComputeWrite);
  splat_->bind(cmd, set_.set());
  splat_->push(cmd, params_);
  splat_->dispatch(cmd, params_.counts.y * params_.counts.w);  // per triangle and z slice
  vk::memoryBarrier(ctx_, cmd, vk::BufferUse::ComputeWrite, vk::BufferUse::ComputeWrite);
  finish_->bind(cmd, set_.set());
  finish_->push(cmd, params_);
  finish_->dispatch(cmd, params_.dims.y * params_.dims.z);  // one invocation per row along x
  vk::memoryBarrier(ctx_, cmd, vk::BufferUse::ComputeWrite, vk::BufferUse::ComputeRead);
  vk::memoryBarrier(ctx_, cmd, vk::BufferUse::ComputeWrite, vk::BufferUse::TransferSrc);
  return true;
}
}  // namespace hp
