#pragma once
// Contract: a signed distance grid on the device in the layout of shaders/shared/sdf.h (header, then
// node values), uploaded once at construction and read by shaders that include sdf_collide.glsl.
// Without a grid it holds a header marked absent, so the binding is always valid. Throws hp::Error
// when the grid is past the device's maxStorageBufferRange.
#include <memory>

#include "engine/core/hair/sdf_grid.h"
#include "engine/vk/buffer.h"

namespace hp {
class SdfBuffer {
 public:
  SdfBuffer(const vk::Context& ctx, const std::shared_ptr<const SdfGrid>& grid);
  const vk::Buffer& buffer() const { return buffer_; }
  const std::shared_ptr<const SdfGrid>& grid() const { return grid_; }

 private:
  std::shared_ptr<const SdfGrid> grid_;
  vk::Buffer buffer_;
};

// The bytes SdfBuffer uploads (for tests).
std::vector<float> packSdf(const SdfGrid* grid);
}  // namespace hp
