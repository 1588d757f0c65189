#pragma once
// Contract: writes a whole file or nothing. The bytes go to a temporary file in the destination's
// directory, which is flushed and then renamed over the destination, so a reader (or a failure half
// way) never sees a partial file. A symbolic link is followed: its target is the file written, the link
// stays. Something there that is not a regular file (a device such as /dev/null, a FIFO, a folder), or a
// link that cannot be followed (to a missing file, a loop), is refused, never replaced. Throws hp::Error naming the path on any failure.
#include <cstddef>
#include <filesystem>
#include <span>

namespace hp {
// The file writeFileAtomically(path) replaces: `path`, or the file its link names. Throws hp::Error, as the
// write would, for something that is not a regular file or a link that cannot be followed: callers check
// their outputs with it before any work.
std::filesystem::path atomicWriteDestination(const std::filesystem::path& path);

void writeFileAtomically(const std::filesystem::path& path, std::span<const std::byte> bytes);

// Removes the file at `path` if there is one, before a set of files it describes is rewritten (it is then
// written last, so a failure half way leaves none beside files it does not describe). Throws hp::Error naming
// the path if it cannot be removed.
void removeBeforeRewrite(const std::filesystem::path& path);

// The same for files that are only a cache of values that can be made again (engine/core/disk_cache.h): whatever
// is at `path` but a folder is replaced, a link itself and not the file it names (a link planted in a cache folder
// cannot redirect the write), and the file is not flushed to the disk before the rename (a torn file after a crash
// fails its checksum and is made again). Throws hp::Error naming the path on any failure; no temporary is left.
void replaceCacheFile(const std::filesystem::path& path, std::span<const std::byte> bytes);
}  // namespace hp
