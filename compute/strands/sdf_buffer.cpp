#include "compute/strands/sdf_buffer.h"

#include <cstring>
#include <string>

#include "engine/core/error.h"
#include "engine/vk/context.h"
#include "engine/vk/transfer.h"
#include "shaders/shared/sdf.h"

namespace hp {
std::vector<float> packSdf(const SdfGrid* grid) {
  gpu::SdfHeader header{};
  if (grid && !grid->empty()) {
    header.originCell = glm::vec4(grid->origin, grid->cell);
    header.dims = glm::uvec4(grid->dims, 1u);
  }
  constexpr std::size_t headerFloats = sizeof(gpu::SdfHeader) / sizeof(float);
  std::vector<float> out(headerFloats + (header.dims.w ? grid->values.size() : 1));
  std::memcpy(out.data(), &header, sizeof header);
  if (header.dims.w) std::memcpy(out.data() + headerFloats, grid->values.data(), grid->values.size() * sizeof(float));
  return out;
}

SdfBuffer::SdfBuffer(const vk::Context& ctx, const std::shared_ptr<const SdfGrid>& grid) : grid_(grid) {
  const std::vector<float> packed = packSdf(grid.get());
  const VkDeviceSize bytes = packed.size() * sizeof(float);
  if (bytes > ctx.properties().limits.maxStorageBufferRange)
    throw Error("simulation: the distance grid needs " + std::to_string(bytes) +
                " bytes, past this device's maxStorageBufferRange of " +
                std::to_string(ctx.properties().limits.maxStorageBufferRange) + " (use a larger cell)");
  buffer_ = vk::Buffer(ctx, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                       vk::MemoryKind::DeviceLocal, "distance grid");
  vk::upload<float>(ctx, buffer_, packed, vk::BufferUse::ComputeRead);
}
}  // namespace hp
