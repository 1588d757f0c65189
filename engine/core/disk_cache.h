#pragma once
// Contract: costly pure results kept on disk between processes, opt-in: a folder given explicitly or by the
// environment variable HAIRPIPE_CACHE_DIR (unset or empty: no cache). An entry is one file holding the build
// identity of the code that made it (build_identity.h), its kind, the whole key it was made from, the value and a
// checksum over all of it; load returns the value only when all of them match, so a damaged, truncated, foreign
// or stale file (another build, another key with the same hash) is a miss, never a wrong value. store writes the
// file atomically (a reader never sees half of one) and never throws: a folder that cannot be made or written
// means no cache, nothing more. Any number of processes may share a folder. A store removes the entries of the
// same kind that other builds made (they would never be read again by this one, and a developer's rebuilds would
// otherwise pile them up); nothing else in the folder is touched.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <span>
#include <utility>
#include <string_view>
#include <vector>

namespace hp {
class DiskCache {
 public:
  explicit DiskCache(std::filesystem::path folder) : folder_(std::move(folder)) {}
  // The process's cache: HAIRPIPE_CACHE_DIR as it was at the first call.
  static const DiskCache& process();

  bool enabled() const { return !folder_.empty(); }
  const std::filesystem::path& folder() const { return folder_; }
  // kind: a short name of letters, digits and '-' (the file's name starts with it).
  std::optional<std::vector<std::byte>> load(std::string_view kind, std::span<const std::byte> key) const;
  // Never throws (and is not noexcept: the library references no std::terminate).
  void store(std::string_view kind, std::span<const std::byte> key, std::span<const std::byte> value) const;
  // The file an entry lives in (whether or not it exists).
  std::filesystem::path entryPath(std::string_view kind, std::span<const std::byte> key) const;

 private:
  void removeOtherBuilds(std::string_view kind) const;
  std::filesystem::path folder_;
};
}  // namespace hp
