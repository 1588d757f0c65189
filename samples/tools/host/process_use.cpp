#include "samples/tools/host/process_use.h"

#include <dirent.h>
#include <unistd.h>

#include <fstream>
#include <string>

namespace hp {
namespace {
long entriesOf(const char* dir) {
  DIR* d = opendir(dir);
  if (!d) return -1;
  long n = 0;
  while (readdir(d)) ++n;
  closedir(d);
  return n - 2;  // . and ..
}

long statusField(const std::string& key) {  // a "Key:  value" line of /proc/self/status
  std::ifstream in("/proc/self/status");
  for (std::string line; std::getline(in, line);)
    if (line.rfind(key + ":", 0) == 0) return std::stol(line.substr(key.size() + 1));
  return -1;
}
}  // namespace

std::uint64_t residentBytes() {
  std::ifstream statm("/proc/self/statm");
  std::uint64_t pages = 0, resident = 0;
  if (!(statm >> pages >> resident)) return 0;
  return resident * std::uint64_t(sysconf(_SC_PAGESIZE));
}

ProcessUse processUse() {
  ProcessUse u;
  u.residentBytes = residentBytes();
  const long fds = entriesOf("/proc/self/fd");
  u.fds = fds < 0 ? -1 : fds - 1;  // less the directory stream counting them
  u.threads = statusField("Threads");
  std::ifstream maps("/proc/self/maps");
  if (maps) {
    u.mappings = 0;
    for (std::string line; std::getline(maps, line);) ++u.mappings;
  }
  return u;
}
}  // namespace hp
