#include "engine/core/hair/input_file.h"

#include <algorithm>
#include <cstdio>
#include <fstream>

#include "engine/core/error.h"

namespace hp {
namespace {
std::string sizeText(std::uint64_t bytes) {
  if (bytes >= (1ull << 20)) return std::to_string(bytes >> 20) + " MiB";
  return std::to_string(bytes) + " bytes";
}

// The file's size after the checks that need no read: exists, regular, within the limit.
std::uint64_t checkedSize(const std::filesystem::path& path, std::uint64_t maxBytes) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (ec || !std::filesystem::exists(status)) throw Error(path.string() + ": cannot open (no such input file)");
  if (std::filesystem::is_directory(status)) throw Error(path.string() + ": cannot open (not a regular file: a directory)");
  if (!std::filesystem::is_regular_file(status)) throw Error(path.string() + ": cannot open (not a regular file)");
  const std::uint64_t size = std::filesystem::file_size(path, ec);
  if (ec) throw Error(path.string() + ": cannot tell the file's size (" + ec.message() + ")");
  if (size > maxBytes)
    throw Error(path.string() + ": the file is " + sizeText(size) + ", more than the " + sizeText(maxBytes) +
                " this kind of input may hold");
  return size;
}

template <typename Container>
Container readChecked(const std::filesystem::path& path, std::uint64_t maxBytes) {
  const std::uint64_t size = checkedSize(path, maxBytes);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path.string() + ": cannot open");
  Container out(static_cast<std::size_t>(size), typename Container::value_type{});
  if (size && !in.read(reinterpret_cast<char*>(out.data()), static_cast<std::streamsize>(size)))
    throw Error(path.string() + ": read error (the file changed or shrank while being read)");
  return out;
}
}  // namespace

std::vector<std::byte> readInputBytes(const std::filesystem::path& path, std::uint64_t maxBytes) {
  return readChecked<std::vector<std::byte>>(path, maxBytes);
}

std::string readInputText(const std::filesystem::path& path, std::uint64_t maxBytes) {
  return readChecked<std::string>(path, maxBytes);
}

std::vector<std::string_view> splitWords(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t at = 0;
  while ((at = line.find_first_not_of(" \t\r", at)) != std::string_view::npos) {
    const std::size_t end = std::min(line.find_first_of(" \t\r", at), line.size());
    out.push_back(line.substr(at, end - at));
    at = end;
  }
  return out;
}

std::string excerpt(std::string_view text, std::size_t maxChars) {
  std::string out;
  std::size_t shown = 0;
  for (; shown < text.size() && out.size() < maxChars; ++shown) {
    const auto c = static_cast<unsigned char>(text[shown]);
    if (c >= 32 && c < 127) {
      out += static_cast<char>(c);
    } else {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02x", c);
      out += hex;
    }
  }
  if (shown < text.size()) out += "...";
  return out;
}
}  // namespace hp
