#pragma once
// Contract: reads a whole input file that a user named, or refuses it with hp::Error naming the path
// and the reason: missing, not a regular file (directory, device such as /dev/zero, FIFO), larger
// than the caller's limit (checked before anything is read, so a huge or endless file costs nothing),
// or a read error. Every parser of user files reads through here, so no parser opens a file itself.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace hp {
// Upper bounds per kind of input, far above any real asset but below what would exhaust memory.
inline constexpr std::uint64_t kMaxHairFileBytes = 4ull << 30;    // .hair / .tfx: 4 GiB
inline constexpr std::uint64_t kMaxMeshFileBytes = 1ull << 30;    // OBJ: 1 GiB
inline constexpr std::uint64_t kMaxTextFileBytes = 16ull << 20;   // scene JSON: 16 MiB
inline constexpr std::uint64_t kMaxTableFileBytes = 256ull << 20; // CSV query tables: 256 MiB
inline constexpr std::uint64_t kMaxImageFileBytes = 4ull << 30;   // PNG / PFM images: 4 GiB

std::vector<std::byte> readInputBytes(const std::filesystem::path& path, std::uint64_t maxBytes);
std::string readInputText(const std::filesystem::path& path, std::uint64_t maxBytes);

// At most `maxChars` characters of `text` for an error message, with "..." when cut and every
// non-printable byte escaped, so a message never carries a whole hostile input.
std::string excerpt(std::string_view text, std::size_t maxChars = 48);

// The words of a text line, split at blanks (spaces, tabs, a carriage return).
std::vector<std::string_view> splitWords(std::string_view line);
}  // namespace hp
