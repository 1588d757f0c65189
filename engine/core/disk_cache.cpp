#include "engine/core/disk_cache.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#ifdef __GLIBC__
#include <gnu/libc-version.h>
#endif

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>

#include "engine/core/build_identity.h"
#include "engine/core/byte_stream.h"
#include "engine/core/error.h"
#include "engine/core/fnv1a.h"
#include "engine/core/hair/atomic_write.h"

namespace hp {
namespace {
namespace fs = std::filesystem;
using Magic = std::array<char, 8>;
constexpr Magic kMagic = {'h', 'p', 'c', 'a', 'c', 'h', 'e', '2'};  // the last character: the layout's version
// Larger entries are neither written nor read (a million-vertex mesh's skin transfer is ~130 MB).
constexpr std::uintmax_t kMaxEntryBytes = std::uintmax_t(1) << 30;
// A temporary older than this was left by a process that died while writing it.
constexpr auto kStaleTemporary = std::chrono::minutes(10);

std::span<const std::byte> bytesOf(std::string_view text) { return std::as_bytes(std::span(text.data(), text.size())); }

// What an entry's values depend on beyond the build: the C library's maths (its version, the CPU features by which
// it picks its sin, exp and log at run time, and the tunables that can override that pick), so a folder shared
// between machines never mixes their bits.
const std::string& entryIdentity() {
  static const std::string identity = [] {
    std::string id = buildIdentity();
#ifdef __GLIBC__
    id += std::string(" glibc ") + gnu_get_libc_version();
#endif
#if defined(__x86_64__) || defined(__i386__)
    // glibc's x86 maths: the FMA forms where FMA and AVX2 both are, else FMA4's where it is, else SSE2's.
    __builtin_cpu_init();
    id += __builtin_cpu_supports("fma") && __builtin_cpu_supports("avx2") ? " fma+avx2"
          : __builtin_cpu_supports("fma4")                                ? " fma4"
                                                                          : " sse2";
#endif
    if (const char* tunables = std::getenv("GLIBC_TUNABLES")) id += std::string(" tunables ") + tunables;
    return id;
  }();
  return identity;
}

void checkKind(std::string_view kind) {
  const bool plain = !kind.empty() && std::all_of(kind.begin(), kind.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-';
  });
  if (!plain) throw Error("disk cache: kind '" + std::string(kind) + "' is not lower-case letters, digits and '-'");
}

// The whole file, or nothing when it is missing, a link, not a regular file (opened without blocking: a FIFO
// would block a plain open) or too large.
std::optional<std::vector<std::byte>> readEntry(const fs::path& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOFOLLOW | O_CLOEXEC);
  if (fd < 0) return std::nullopt;
  std::optional<std::vector<std::byte>> bytes;
  struct stat st {};
  if (::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && std::uintmax_t(st.st_size) <= kMaxEntryBytes) {
    bytes.emplace(static_cast<std::size_t>(st.st_size));
    std::size_t done = 0;
    while (done < bytes->size()) {
      const ssize_t n = ::read(fd, bytes->data() + done, bytes->size() - done);
      if (n <= 0) break;  // an error or a file cut short while read: a miss
      done += static_cast<std::size_t>(n);
    }
    if (done != bytes->size()) bytes.reset();
  }
  ::close(fd);
  return bytes;
}

// The value of an entry's bytes when they are whole and were made by this build, on this C library, for this kind
// and key.
std::optional<std::vector<std::byte>> entryValue(std::span<const std::byte> file, std::string_view kind,
                                                 std::span<const std::byte> key) {
  if (file.size() < sizeof(std::uint64_t)) return std::nullopt;
  const std::span<const std::byte> body = file.first(file.size() - sizeof(std::uint64_t));
  if (ByteReader(file.last(sizeof(std::uint64_t))).get<std::uint64_t>() != fnv1a(body)) return std::nullopt;
  ByteReader in(body);
  if (in.get<Magic>() != kMagic || in.getString() != entryIdentity() || in.getString() != kind) return std::nullopt;
  if (in.get<std::uint64_t>() != key.size() || !std::ranges::equal(in.take(key.size(), "the key"), key))
    return std::nullopt;  // compared where it lies: a mesh's key is megabytes
  std::vector<std::byte> value = in.getVector<std::byte>();
  if (!in.atEnd()) return std::nullopt;
  return value;
}

std::vector<std::byte> entryBytes(std::string_view kind, std::span<const std::byte> key,
                                  std::span<const std::byte> value) {
  ByteWriter out;
  out.put(kMagic);
  out.putString(entryIdentity());
  out.putString(kind);
  out.putVector(key);
  out.putVector(value);
  out.put(fnv1a(out.bytes()));
  return out.take();
}

// The parts of a file name in a cache folder: kind-<32 hex build>-<8 hex machine>-<16 hex key>.bin (machine: the
// C library's part of the identity, so machines sharing a folder keep apart entries), or a temporary of one
// (.kind-...bin.tmp-XXXXXX, as writeFileAtomically's sibling replaceCacheFile names it).
struct EntryName {
  bool entry = false, temporary = false;
  std::string build;
};

bool hexAt(const std::string& text, std::size_t at, std::size_t count) {
  return std::all_of(text.begin() + std::ptrdiff_t(at), text.begin() + std::ptrdiff_t(at + count),
                     [](char c) { return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'); });
}

EntryName parseName(const std::string& name, std::string_view kind) {
  const std::string prefix = std::string(kind) + "-";
  const std::size_t length = prefix.size() + 32 + 1 + 8 + 1 + 16 + 4;
  EntryName parsed;
  const std::size_t build = prefix.size(), machine = build + 33, key = machine + 9;
  if (name.size() == length && name.starts_with(prefix) && name.ends_with(".bin") && name[machine - 1] == '-' &&
      name[key - 1] == '-' && hexAt(name, build, 32) && hexAt(name, machine, 8) && hexAt(name, key, 16)) {
    parsed.entry = true;
    parsed.build = name.substr(prefix.size(), 32);
  } else if (name.size() == 1 + length + 11 && name[0] == '.' && name.compare(1, prefix.size(), prefix) == 0 &&
             name.compare(1 + length, 5, ".tmp-") == 0) {
    parsed.temporary = true;
  }
  return parsed;
}
}  // namespace

const DiskCache& DiskCache::process() {
  // Never destroyed: a detached material build (compute/renderer/lut_build.h) may still use it at exit.
  static const DiskCache& cache = *new DiskCache([] {
    const char* folder = std::getenv("HAIRPIPE_CACHE_DIR");
    return fs::path(folder ? folder : "");
  }());
  return cache;
}

fs::path DiskCache::entryPath(std::string_view kind, std::span<const std::byte> key) const {
  checkKind(kind);
  char hashes[40];
  std::snprintf(hashes, sizeof hashes, "-%08llx-%016llx.bin",
                static_cast<unsigned long long>(fnv1a(bytesOf(entryIdentity())) >> 32),
                static_cast<unsigned long long>(fnv1a(key, fnv1a(bytesOf(kind)))));
  return folder_ / (std::string(kind) + "-" + buildIdentity() + hashes);
}

std::optional<std::vector<std::byte>> DiskCache::load(std::string_view kind, std::span<const std::byte> key) const {
  if (!enabled()) return std::nullopt;
  try {
    const fs::path path = entryPath(kind, key);
    const std::optional<std::vector<std::byte>> file = readEntry(path);
    std::optional<std::vector<std::byte>> value = file ? entryValue(*file, kind, key) : std::nullopt;
    // Used: evicted last. The name's own times (a link swapped in since the read is touched, not what it names).
    if (value) ::utimensat(AT_FDCWD, path.c_str(), nullptr, AT_SYMLINK_NOFOLLOW);
    return value;
  } catch (const std::exception&) {  // a malformed entry (ByteReader), memory: a miss
    return std::nullopt;
  }
}

void DiskCache::store(std::string_view kind, std::span<const std::byte> key, std::span<const std::byte> value) const {
  if (!enabled()) return;
  try {
    const std::vector<std::byte> bytes = entryBytes(kind, key, value);
    if (bytes.size() > kMaxEntryBytes) return;
    fs::create_directories(folder_);
    replaceCacheFile(entryPath(kind, key), bytes);
    prune(kind);
  } catch (...) {  // an unwritable folder, a full disk: the value is simply not kept
  }
}

void DiskCache::prune(std::string_view kind) const {
  struct Kept {
    fs::path path;
    fs::file_time_type used;
    std::uintmax_t bytes;
  };
  std::vector<Kept> kept;
  std::error_code ec;
  const auto now = fs::file_time_type::clock::now();
  for (const auto& file : fs::directory_iterator(folder_, ec)) {
    const EntryName name = parseName(file.path().filename().string(), kind);
    if (!name.entry && !name.temporary) continue;
    if (file.is_symlink(ec) || !file.is_regular_file(ec)) continue;
    const fs::file_time_type used = file.last_write_time(ec);
    if (ec) continue;
    if ((name.entry && name.build != buildIdentity()) || (name.temporary && now - used > kStaleTemporary))
      fs::remove(file.path(), ec);
    else if (const std::uintmax_t bytes = file.file_size(ec); name.entry && !ec)
      kept.push_back({file.path(), used, bytes});
  }
  std::ranges::sort(kept, [](const Kept& a, const Kept& b) { return a.used > b.used; });  // most recent first
  std::uintmax_t total = 0;
  for (const Kept& k : kept)
    if ((total += k.bytes) > maxKindBytes_) fs::remove(k.path, ec);  // a load marks an entry used
}
}  // namespace hp
