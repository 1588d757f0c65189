#include "engine/core/disk_cache.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>

#include "engine/core/build_identity.h"
#include "engine/core/byte_stream.h"
#include "engine/core/error.h"
#include "engine/core/hair/atomic_write.h"

namespace hp {
namespace {
using Magic = std::array<char, 8>;
constexpr Magic kMagic = {'h', 'p', 'c', 'a', 'c', 'h', 'e', '1'};  // the last character: the layout's version
// Larger files are not read: no entry hairpipe makes comes near (a million-vertex mesh's skin transfer is ~130 MB).
constexpr std::uintmax_t kMaxEntryBytes = std::uintmax_t(1) << 30;

std::uint64_t fnv1a(std::span<const std::byte> bytes, std::uint64_t h = 14695981039346656037ull) {
  for (std::byte b : bytes) h = (h ^ std::to_integer<std::uint64_t>(b)) * 1099511628211ull;
  return h;
}

std::span<const std::byte> bytesOf(std::string_view text) { return std::as_bytes(std::span(text.data(), text.size())); }

void checkKind(std::string_view kind) {
  const bool plain = !kind.empty() && std::all_of(kind.begin(), kind.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-';
  });
  if (!plain) throw Error("disk cache: kind '" + std::string(kind) + "' is not lower-case letters, digits and '-'");
}

// The whole file, or nothing when it is missing, not a regular file (a FIFO would block) or too large.
std::optional<std::vector<std::byte>> readEntry(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return std::nullopt;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec || size > kMaxEntryBytes) return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  std::vector<std::byte> bytes(static_cast<std::size_t>(size));
  if (!in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()))) return std::nullopt;
  if (in.peek() != std::char_traits<char>::eof()) return std::nullopt;  // grew while read: another writer's
  return bytes;
}

// The value of an entry's bytes when they are whole and were made by this build for this kind and key.
std::optional<std::vector<std::byte>> entryValue(std::span<const std::byte> file, std::string_view kind,
                                                 std::span<const std::byte> key) {
  if (file.size() < sizeof(std::uint64_t)) return std::nullopt;
  const std::span<const std::byte> body = file.first(file.size() - sizeof(std::uint64_t));
  if (ByteReader(file.last(sizeof(std::uint64_t))).get<std::uint64_t>() != fnv1a(body)) return std::nullopt;
  ByteReader in(body);
  if (in.get<Magic>() != kMagic || in.getString() != buildIdentity() || in.getString() != kind) return std::nullopt;
  const std::vector<std::byte> storedKey = in.getVector<std::byte>();
  if (!std::ranges::equal(storedKey, key)) return std::nullopt;
  std::vector<std::byte> value = in.getVector<std::byte>();
  if (!in.atEnd()) return std::nullopt;
  return value;
}
}  // namespace

const DiskCache& DiskCache::process() {
  // Never destroyed: a detached material build (compute/renderer/lut_build.h) may still use it at exit.
  static const DiskCache& cache = *new DiskCache([] {
    const char* folder = std::getenv("HAIRPIPE_CACHE_DIR");
    return std::filesystem::path(folder ? folder : "");
  }());
  return cache;
}

std::filesystem::path DiskCache::entryPath(std::string_view kind, std::span<const std::byte> key) const {
  checkKind(kind);
  char hash[24];
  std::snprintf(hash, sizeof hash, "-%016llx.bin", static_cast<unsigned long long>(fnv1a(key, fnv1a(bytesOf(kind)))));
  return folder_ / (std::string(kind) + "-" + buildIdentity() + hash);
}

void DiskCache::removeOtherBuilds(std::string_view kind) const {
  const std::string prefix = std::string(kind) + "-", ours = prefix + buildIdentity() + "-";
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(folder_, ec)) {
    const std::string name = entry.path().filename().string();
    // kind-<32 hex identity>-<16 hex key hash>.bin, of another identity
    const bool ofKind = name.size() == prefix.size() + 32 + 1 + 16 + 4 && name.starts_with(prefix) &&
                        name.ends_with(".bin") && name[prefix.size() + 32] == '-';
    if (ofKind && !name.starts_with(ours) && entry.is_regular_file(ec)) std::filesystem::remove(entry.path(), ec);
  }
}

std::optional<std::vector<std::byte>> DiskCache::load(std::string_view kind, std::span<const std::byte> key) const {
  if (!enabled()) return std::nullopt;
  try {
    const std::optional<std::vector<std::byte>> file = readEntry(entryPath(kind, key));
    return file ? entryValue(*file, kind, key) : std::nullopt;
  } catch (const std::exception&) {  // a malformed entry (ByteReader), memory: a miss
    return std::nullopt;
  }
}

void DiskCache::store(std::string_view kind, std::span<const std::byte> key,
                      std::span<const std::byte> value) const {
  if (!enabled()) return;
  try {
    ByteWriter out;
    out.put(kMagic);
    out.putString(buildIdentity());
    out.putString(kind);
    out.putVector(key);
    out.putVector(value);
    out.put(fnv1a(out.bytes()));
    std::filesystem::create_directories(folder_);
    writeFileAtomically(entryPath(kind, key), out.bytes());
    removeOtherBuilds(kind);
  } catch (...) {  // an unwritable folder, a full disk: the value is simply not kept
  }
}
}  // namespace hp
