#pragma once
// Helpers for the host-only asset tests: a per-test temporary directory, file writing, and
// expectations on hp::Error messages.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <span>
#include <string>
#include <vector>

#include "engine/core/error.h"

namespace hp::test {
// A fresh directory under the system temp dir, removed when the object dies.
class TempDir {
 public:
  TempDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = std::string("hairpipe-") + (info ? info->test_suite_name() : "x") + "-" +
                       (info ? info->name() : "y") + "-" + std::to_string(::getpid());
    path_ = std::filesystem::temp_directory_path() / name;
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~TempDir() { std::filesystem::remove_all(path_); }
  std::filesystem::path operator/(const std::string& file) const { return path_ / file; }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

inline void writeText(const std::filesystem::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

// The file's inode number (0 when it is missing): a file replaced by a rename has a new one.
inline ino_t inodeOf(const std::filesystem::path& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 ? st.st_ino : 0;
}

inline std::vector<std::byte> readBytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  const std::vector<char> chars{std::istreambuf_iterator<char>(in), {}};
  const auto bytes = std::as_bytes(std::span(chars));
  return {bytes.begin(), bytes.end()};
}

inline void writeBytes(const std::filesystem::path& path, const std::vector<std::byte>& bytes) {
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()),
                                              static_cast<std::streamsize>(bytes.size()));
}

// The message of the hp::Error that fn throws; fails the test if it throws nothing or something else.
inline std::string errorOf(const std::function<void()>& fn) {
  try {
    fn();
  } catch (const hp::Error& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "threw a non-hp::Error: " << e.what();
    return {};
  }
  ADD_FAILURE() << "did not throw";
  return {};
}
}  // namespace hp::test

#define EXPECT_ERROR_CONTAINS(statement, text) \
  EXPECT_THAT_ERROR_CONTAINS_IMPL(::hp::test::errorOf([&] { statement; }), text)
#define EXPECT_THAT_ERROR_CONTAINS_IMPL(message, text)                                   \
  do {                                                                                   \
    std::string hp_msg_ = (message);                                                     \
    EXPECT_NE(hp_msg_.find(text), std::string::npos) << "message: " << hp_msg_;          \
  } while (0)
