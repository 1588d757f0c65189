#include "engine/hair/atomic_write.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>

#include "engine/error.h"

namespace hp {
namespace {
void writeAll(int fd, std::span<const std::byte> bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw errno;
    done += static_cast<std::size_t>(n);
  }
}
}  // namespace

void writeFileAtomically(const std::filesystem::path& path, std::span<const std::byte> bytes) {
  std::filesystem::path dir = path.parent_path().empty() ? "." : path.parent_path();
  std::string name = path.filename().string();
  name.insert(0, 1, '.');  // hidden while incomplete (and avoids a GCC 12 -Wrestrict false positive)
  name += ".tmp-XXXXXX";
  std::string tmpl = (dir / name).string();
  int fd = ::mkstemp(tmpl.data());
  if (fd < 0) throw Error(path.string() + ": cannot create a temporary file: " + std::strerror(errno));
  try {
    writeAll(fd, bytes);
    ::fchmod(fd, 0644);  // mkstemp creates 0600; a written asset should be readable like any file
    if (::fsync(fd) != 0) throw errno;
    if (::close(fd) != 0) { fd = -1; throw errno; }
    fd = -1;
    if (std::rename(tmpl.c_str(), path.c_str()) != 0) throw errno;
  } catch (int err) {
    if (fd >= 0) ::close(fd);
    std::remove(tmpl.c_str());
    throw Error(path.string() + ": cannot write: " + std::strerror(err));
  }
}
}  // namespace hp
