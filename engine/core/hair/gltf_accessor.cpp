#include "engine/core/hair/gltf_accessor.h"

#include <algorithm>
#include <cstring>

#include "engine/core/error.h"

namespace hp {
namespace {
double component(const unsigned char* p, int type, bool normalized) {
  auto load = [p](auto v) {
    std::memcpy(&v, p, sizeof v);
    return v;
  };
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: return normalized ? std::max(load(std::int8_t()) / 127.0, -1.0) : load(std::int8_t());
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? load(std::uint8_t()) / 255.0 : load(std::uint8_t());
    case TINYGLTF_COMPONENT_TYPE_SHORT: return normalized ? std::max(load(std::int16_t()) / 32767.0, -1.0) : load(std::int16_t());
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return normalized ? load(std::uint16_t()) / 65535.0 : load(std::uint16_t());
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return load(std::uint32_t());
    case TINYGLTF_COMPONENT_TYPE_FLOAT: return load(float());
    default: return 0.0;
  }
}

bool oneOf(int v, const std::vector<int>& list) { return std::find(list.begin(), list.end(), v) != list.end(); }
}  // namespace

std::uint64_t readAccessor(const AccessorRead& r, int index,
                           const std::function<void(std::uint64_t, const std::array<double, 16>&)>& element) {
  const std::string what = r.source + ": " + r.what;
  if (index < 0 || std::size_t(index) >= r.model.accessors.size())
    throw Error(what + " names accessor " + std::to_string(index) + " of " + std::to_string(r.model.accessors.size()));
  const tinygltf::Accessor& a = r.model.accessors[std::size_t(index)];
  if (a.sparse.isSparse) throw Error(what + ": sparse accessors are not read");
  if (!oneOf(a.type, r.types) || !oneOf(a.componentType, r.components))
    throw Error(what + ": accessor " + std::to_string(index) + " has element type " + std::to_string(a.type) +
                " / component type " + std::to_string(a.componentType) + ", not one this attribute takes");
  if (a.count > r.maxCount) throw Error(what + ": " + std::to_string(a.count) + " elements, more than " + std::to_string(r.maxCount));
  if (a.bufferView < 0 || std::size_t(a.bufferView) >= r.model.bufferViews.size())
    throw Error(what + ": accessor " + std::to_string(index) + " has no buffer view");
  const tinygltf::BufferView& v = r.model.bufferViews[std::size_t(a.bufferView)];
  if (v.buffer < 0 || std::size_t(v.buffer) >= r.model.buffers.size()) throw Error(what + ": its buffer view has no buffer");
  const std::vector<unsigned char>& data = r.model.buffers[std::size_t(v.buffer)].data;
  if (v.byteOffset > data.size() || v.byteLength > data.size() || a.byteOffset > data.size() || v.byteStride > 4096)
    throw Error(what + ": accessor " + std::to_string(index) + "'s offsets or stride are past its buffer");
  const int n = tinygltf::GetNumComponentsInType(std::uint32_t(a.type));
  const int size = tinygltf::GetComponentSizeInBytes(std::uint32_t(a.componentType));
  const std::uint64_t elementBytes = std::uint64_t(n) * std::uint64_t(size);
  const std::uint64_t stride = v.byteStride ? std::uint64_t(v.byteStride) : elementBytes;
  const std::uint64_t viewEnd = std::uint64_t(v.byteOffset) + v.byteLength;
  const std::uint64_t first = std::uint64_t(v.byteOffset) + a.byteOffset;
  const std::uint64_t end = a.count == 0 ? first : first + stride * (a.count - 1) + elementBytes;
  if (n <= 0 || n > 16 || size <= 0 || stride < elementBytes || end > viewEnd || viewEnd > data.size())
    throw Error(what + ": accessor " + std::to_string(index) + " reaches past its buffer view or buffer");
  std::array<double, 16> values{};
  for (std::uint64_t i = 0; i < a.count; ++i) {
    const unsigned char* p = data.data() + first + stride * i;
    for (int c = 0; c < n; ++c) values[std::size_t(c)] = component(p + std::size_t(c) * std::size_t(size), a.componentType, a.normalized);
    element(i, values);
  }
  return a.count;
}
}  // namespace hp
