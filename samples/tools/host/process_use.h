#pragma once
// Contract: what this process holds now, from Linux's /proc/self (0 or -1 where it cannot be read): its
// resident memory, open file descriptors, threads and memory mappings. For the benches' memory column and
// the tests that check repeated work gives back what it takes.
#include <cstdint>

namespace hp {
struct ProcessUse {
  std::uint64_t residentBytes = 0;  // /proc/self/statm's resident pages x the page size
  long fds = -1;                    // entries of /proc/self/fd, less the one listing them
  long threads = -1;                // /proc/self/status "Threads:"
  long mappings = -1;               // lines of /proc/self/maps
};

ProcessUse processUse();
std::uint64_t residentBytes();  // processUse().residentBytes alone, without the other reads
}  // namespace hp
