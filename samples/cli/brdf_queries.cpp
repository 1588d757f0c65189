#include "samples/cli/brdf_queries.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <system_error>

#include "engine/core/error.h"
#include "engine/core/hair/input_file.h"

namespace hp::cli {
namespace {
constexpr int kColumns = 9;

std::string_view trim(std::string_view s) {
  const char* ws = " \t\r\n";
  const auto b = s.find_first_not_of(ws);
  if (b == std::string_view::npos) return {};
  return s.substr(b, s.find_last_not_of(ws) - b + 1);
}

std::vector<std::string_view> splitFields(std::string_view line) {
  std::vector<std::string_view> fields;
  for (std::size_t start = 0;;) {
    const std::size_t comma = line.find(',', start);
    fields.push_back(trim(line.substr(start, comma == std::string_view::npos ? comma : comma - start)));
    if (comma == std::string_view::npos) return fields;
    start = comma + 1;
  }
}

enum class Parse { Ok, NotANumber, OutOfRange };

Parse parseNumber(std::string_view field, double& value) {
  if (!field.empty() && field.front() == '+') field.remove_prefix(1);  // from_chars refuses a '+' sign
  const char* end = field.data() + field.size();
  auto [ptr, ec] = std::from_chars(field.data(), end, value);
  if (field.empty() || ptr != end) return Parse::NotANumber;
  if (ec == std::errc::result_out_of_range) return Parse::OutOfRange;
  return ec == std::errc() ? Parse::Ok : Parse::NotANumber;
}

// Unit vector in double, scaled first so neither tiny nor huge finite components under/overflow.
glm::dvec3 unitOrThrow(glm::dvec3 v, const char* name, const std::string& where) {
  const double scale = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
  if (scale == 0.0) throw Error(where + ": " + name + " is a zero-length vector");
  v /= scale;
  return v / std::sqrt(glm::dot(v, v));
}

}  // namespace

std::vector<render::BrdfQuery> parseBrdfQueries(std::string_view text, const std::string& source) {
  std::vector<render::BrdfQuery> rows;
  bool seenContent = false;
  std::size_t lineNo = 0;
  for (std::size_t start = 0; start < text.size();) {
    const std::size_t newline = text.find('\n', start);
    const std::string_view line = text.substr(start, newline == std::string_view::npos ? newline : newline - start);
    start = newline == std::string_view::npos ? text.size() : newline + 1;
    ++lineNo;
    if (trim(line).empty()) continue;
    const std::string where = source + ":" + std::to_string(lineNo);
    const std::vector<std::string_view> fields = splitFields(line);
    const bool first = !seenContent;
    seenContent = true;
    double v[kColumns];
    int numeric = 0;
    for (std::size_t i = 0; i < fields.size() && i < kColumns; ++i) numeric += parseNumber(fields[i], v[i]) != Parse::NotANumber;
    if (first && numeric == 0) continue;  // a header line
    if (fields.size() != kColumns)
      throw Error(where + ": expected " + std::to_string(kColumns) + " comma-separated values (" + kBrdfRowFormat +
                      "), got " + std::to_string(fields.size()));
    for (int i = 0; i < kColumns; ++i) {
      const std::string column = "column " + std::to_string(i + 1) + " ('" + excerpt(fields[i]) + "')";
      switch (parseNumber(fields[i], v[i])) {
        case Parse::NotANumber: throw Error(where + ": " + column + " is not a number");
        case Parse::OutOfRange: throw Error(where + ": " + column + " is out of range");
        case Parse::Ok: break;
      }
      if (!std::isfinite(v[i])) throw Error(where + ": " + column + " is not finite");
    }
    rows.push_back({glm::vec3(unitOrThrow({v[0], v[1], v[2]}, "L", where)),
                    glm::vec3(unitOrThrow({v[3], v[4], v[5]}, "V", where)),
                    glm::vec3(unitOrThrow({v[6], v[7], v[8]}, "T", where))});
  }
  if (rows.empty()) throw Error(source + ": no data rows (expected lines " + std::string(kBrdfRowFormat) + ")");
  return rows;
}

std::vector<render::BrdfQuery> readBrdfQueries(const std::filesystem::path& path) {
  return parseBrdfQueries(readInputText(path, kMaxTableFileBytes), path.string());
}
}  // namespace hp::cli
