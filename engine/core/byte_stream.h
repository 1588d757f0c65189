#pragma once
// Contract: a flat byte encoding of plain values, strings and vectors of trivially copyable values, in the
// host's own representation: for data that the same build writes and reads back (the disk cache's entries),
// never for files exchanged between machines. ByteReader checks every length against what is left and throws
// hp::Error on a short or malformed stream, so a damaged entry cannot make it read past its buffer or allocate
// more than the stream holds. The reader also serves binary file formats (engine/core/hair/tfx_bone_file.cpp), whose
// readers check the values' meaning themselves.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "engine/core/error.h"

namespace hp {
class ByteWriter {
 public:
  template <typename T>
    requires std::is_trivially_copyable_v<T>
  void put(const T& value) {
    append(&value, sizeof(T));
  }
  template <typename T>
    requires std::is_trivially_copyable_v<T>
  void putVector(std::span<const T> values) {
    put<std::uint64_t>(values.size());
    append(values.data(), values.size_bytes());
  }
  template <typename T>
  void putVector(const std::vector<T>& values) {
    putVector(std::span<const T>(values));
  }
  void putString(std::string_view text) { putVector(std::span<const char>(text.data(), text.size())); }
  const std::vector<std::byte>& bytes() const { return bytes_; }
  std::vector<std::byte> take() { return std::move(bytes_); }

 private:
  void append(const void* data, std::size_t size) {
    const auto* first = static_cast<const std::byte*>(data);
    bytes_.insert(bytes_.end(), first, first + size);
  }
  std::vector<std::byte> bytes_;
};

// Reads front to back. A short stream throws hp::Error "<source>: <what> needs N bytes at byte K, the file has L
// left", naming the value being read: callers reading a file pass its path and what each value is.
class ByteReader {
 public:
  explicit ByteReader(std::span<const std::byte> bytes, std::string source = "byte stream")
      : bytes_(bytes), source_(std::move(source)) {}
  template <typename T>
    requires std::is_trivially_copyable_v<T>
  T get(std::string_view what = "a value") {
    T value;
    std::memcpy(&value, take(sizeof(T), what).data(), sizeof(T));
    return value;
  }
  template <typename T>
    requires std::is_trivially_copyable_v<T>
  std::vector<T> getVector(std::string_view what = "a vector") {
    const auto count = get<std::uint64_t>(what);
    if (count > left() / sizeof(T)) need(left() + 1, what);  // more elements than bytes left: throws
    std::vector<T> values(static_cast<std::size_t>(count));
    if (count > 0) std::memcpy(values.data(), take(values.size() * sizeof(T), what).data(), values.size() * sizeof(T));
    return values;
  }
  std::string getString(std::string_view what = "a string") {
    const std::vector<char> text = getVector<char>(what);
    return {text.begin(), text.end()};
  }
  // The next `count` bytes as they are.
  std::span<const std::byte> take(std::uint64_t count, std::string_view what) {
    need(count, what);
    const std::span<const std::byte> taken = bytes_.subspan(at_, static_cast<std::size_t>(count));
    at_ += static_cast<std::size_t>(count);
    return taken;
  }
  void need(std::uint64_t count, std::string_view what) const {
    if (count > left())
      throw Error(source_ + ": " + std::string(what) + " needs " + std::to_string(count) + " bytes at byte " +
                  std::to_string(at_) + ", the file has " + std::to_string(left()) + " left");
  }
  std::size_t left() const { return bytes_.size() - at_; }
  bool atEnd() const { return at_ == bytes_.size(); }

 private:
  std::span<const std::byte> bytes_;
  std::string source_;
  std::size_t at_ = 0;
};
}  // namespace hp
