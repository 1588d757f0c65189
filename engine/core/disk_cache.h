#pragma once
// Contract: costly pure results kept on disk between processes, opt-in: a folder given explicitly or by the
// environment variable HAIRPIPE_CACHE_DIR (unset or empty: no cache). An entry is one file holding what it was made
// by (the build identity of build_identity.h, the C library's version and the CPU features its maths dispatches on),
// its kind, the whole key it was made from, the value and a checksum over all of it; load returns the value only
// when all of them match, so a damaged, truncated, foreign or stale file (another build, another machine's maths,
// another key with the same hash) is a miss. The checksum finds accidents, not forgeries: whoever may write the
// folder can feed the process values, as with any file it reads. store writes the file whole (a temporary renamed
// over whatever is at the entry's path, a link included: never through it) and never throws: a folder that cannot
// be made or written means no cache, nothing more. Any number of processes may share a folder, machines too (the
// file name holds the C library's part of the identity, so each keeps its own entries). After a store the
// folder holds, of that kind, only this build's entries, at most maxKindBytes of them (1 GiB unless told; the
// least recently stored or read go first), and no temporary a dead process left for more than 10 minutes; nothing
// else in it is touched.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <span>
#include <utility>
#include <string_view>
#include <vector>

namespace hp {
class DiskCache {
 public:
  static constexpr std::uintmax_t kDefaultKindBytes = std::uintmax_t(1) << 30;
  // maxKindBytes: how many bytes of entries of one kind the folder keeps (the least recently used go first).
  explicit DiskCache(std::filesystem::path folder, std::uintmax_t maxKindBytes = kDefaultKindBytes)
      : folder_(std::move(folder)), maxKindBytes_(maxKindBytes) {}
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
  void prune(std::string_view kind) const;
  std::filesystem::path folder_;
  std::uintmax_t maxKindBytes_;
};
}  // namespace hp
