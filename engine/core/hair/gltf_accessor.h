#pragma once
// Contract: a glTF accessor's elements, read with every bound checked first: the accessor's buffer view
// and buffer exist, its component type and element type are ones the caller accepts, and its last
// element ends inside both the view and the buffer (64-bit arithmetic). Sparse accessors and accessors
// without a buffer view are refused. Values come out as doubles (normalised integers mapped to [0, 1] or
// [-1, 1] as glTF says), one element at a time. Errors are hp::Error naming the source and `what`.
#include "engine/core/hair/tinygltf_config.h"

#include <array>
#include <cstdint>
#include <functional>
#include <vector>
#include <string>

namespace hp {
struct AccessorRead {
  const tinygltf::Model& model;
  const std::string& source;
  std::string what;                       // e.g. "mesh 0 primitive 1 POSITION"
  std::vector<int> types;                 // TINYGLTF_TYPE_* accepted
  std::vector<int> components;            // TINYGLTF_COMPONENT_TYPE_* accepted
  std::uint64_t maxCount;
};

// Calls `element(i, values)` for each element (values[0..components-1]); returns the element count.
std::uint64_t readAccessor(const AccessorRead& read, int accessor,
                           const std::function<void(std::uint64_t, const std::array<double, 16>&)>& element);
}  // namespace hp
