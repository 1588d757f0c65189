#pragma once
// Contract: how public hairpipe functions report failure. Nothing in the public API throws: each call that
// can fail returns a Status (success, or a message naming what failed: the parameter and its bad value, the
// file and the problem in it, the Vulkan call and its VkResult) or a Result<T> (a value, or such a Status).
// Usable from code built with -fno-exceptions. Messages are English, one line, and start with the public
// function that failed. value() and operator-> of a failed Result are undefined: check ok() first.
#include <optional>
#include <string>
#include <type_traits>
#include <utility>

namespace hairpipe {
class [[nodiscard]] Status {
 public:
  Status() noexcept = default;  // success
  static Status failure(std::string message) noexcept {
    Status s;
    s.failed_ = true;
    s.message_ = std::move(message);
    return s;
  }
  bool ok() const noexcept { return !failed_; }
  explicit operator bool() const noexcept { return ok(); }
  const std::string& message() const noexcept { return message_; }  // empty on success

 private:
  bool failed_ = false;
  std::string message_;
};

template <class T>
class [[nodiscard]] Result {
 public:
  Result(T value) noexcept(std::is_nothrow_move_constructible_v<T>) : value_(std::move(value)) {}
  Result(Status failure) noexcept : status_(std::move(failure)) {
    if (status_.ok()) status_ = Status::failure("hairpipe::Result: made from a successful Status without a value");
  }
  bool ok() const noexcept { return value_.has_value(); }
  explicit operator bool() const noexcept { return ok(); }
  const Status& status() const noexcept { return status_; }
  const std::string& message() const noexcept { return status_.message(); }
  // The value; only when ok().
  T& value() & noexcept { return *value_; }
  const T& value() const& noexcept { return *value_; }
  T&& value() && noexcept { return std::move(*value_); }
  T* operator->() noexcept { return &*value_; }
  const T* operator->() const noexcept { return &*value_; }

 private:
  std::optional<T> value_;
  Status status_;
};
}  // namespace hairpipe
