#pragma once
// Contract: the tools' JSON reports and files as text. Strings that came from input (a path, a .hair file's
// info field, a bone name) need not be UTF-8: their invalid bytes are written as U+FFFD instead of failing
// the report after its other outputs were written.
#include <nlohmann/json.hpp>

#include <string>

namespace hp {
inline std::string jsonText(const nlohmann::json& value) {
  return value.dump(2, ' ', false, nlohmann::json::error_handler_t::replace);
}
}  // namespace hp
