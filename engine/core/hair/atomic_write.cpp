#include "engine/core/hair/atomic_write.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>

#include "engine/core/error.h"

namespace hp {
namespace {
// 0 on success, else the errno of the failing write.
int writeAll(int fd, std::span<const std::byte> bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return n < 0 ? errno : EIO;
    done += static_cast<std::size_t>(n);
  }
  return 0;
}

// Writes, optionally flushes, and closes fd; 0 on success, else the first errno.
int finishFile(int fd, std::span<const std::byte> bytes, bool flush) {
  int err = writeAll(fd, bytes);
  if (!err) ::fchmod(fd, 0644);  // mkstemp creates 0600; an asset should be readable like any file
  if (!err && flush && ::fsync(fd) != 0) err = errno;
  if (::close(fd) != 0 && !err) err = errno;
  return err;
}

// Writes bytes to a temporary beside `path` and renames it over `path` (which rename replaces as it is, a link
// included).
void writeAndRename(const std::filesystem::path& path, std::span<const std::byte> bytes, bool flush) {
  std::filesystem::path dir = path.parent_path().empty() ? "." : path.parent_path();
  std::string name = path.filename().string();
  name.insert(0, 1, '.');  // hidden while incomplete (and avoids a GCC 12 -Wrestrict false positive)
  name += ".tmp-XXXXXX";
  std::string tmpl = (dir / name).string();
  int fd = ::mkstemp(tmpl.data());
  if (fd < 0) throw Error(path.string() + ": cannot create a temporary file: " + std::strerror(errno));
  int err = finishFile(fd, bytes, flush);
  if (!err && std::rename(tmpl.c_str(), path.c_str()) != 0) err = errno;
  if (err) {
    std::remove(tmpl.c_str());
    throw Error(path.string() + ": cannot write: " + std::strerror(err));
  }
}
}  // namespace

std::filesystem::path atomicWriteDestination(const std::filesystem::path& given) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status link = fs::symlink_status(given, ec);
  if (ec || link.type() == fs::file_type::not_found) return given;
  fs::path path = given;
  if (fs::is_symlink(link)) {
    path = fs::canonical(given, ec);
    if (ec) throw Error(given.string() + ": is a link that cannot be followed (" + ec.message() + "); not written");
  }
  const fs::file_status status = fs::status(path, ec);
  if (ec) throw Error(given.string() + ": cannot be examined (" + ec.message() + "); not written");
  if (!fs::is_regular_file(status))
    throw Error(given.string() + ": exists and is not a regular file (a device, a FIFO or a folder); not replaced");
  return path;
}

void writeFileAtomically(const std::filesystem::path& given, std::span<const std::byte> bytes) {
  writeAndRename(atomicWriteDestination(given), bytes, true);
}

void replaceCacheFile(const std::filesystem::path& path, std::span<const std::byte> bytes) {
  writeAndRename(path, bytes, false);
}

void removeBeforeRewrite(const std::filesystem::path& path) {
  std::error_code ec;
  std::filesystem::remove(path, ec);  // none there: not an error
  if (ec) throw Error("cannot replace " + path.string() + ": " + ec.message());
}
}  // namespace hp
