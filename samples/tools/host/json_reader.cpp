#include "samples/tools/host/json_reader.h"

#include <cmath>
#include <limits>

#include "engine/core/error.h"
#include "engine/core/hair/input_file.h"

namespace hp {
std::string jsonTypeName(const nlohmann::json& value) {
  if (value.is_number()) return "number";
  return value.type_name();
}

nlohmann::json parseJsonText(const std::string& text, const std::string& file) {
  // Depth is bounded while parsing (the parser itself is iterative), so no later recursive copy,
  // comparison or dump of the document can run out of stack on hostile nesting.
  const nlohmann::json::parser_callback_t limitDepth = [&file](int depth, nlohmann::json::parse_event_t event,
                                                                 nlohmann::json&) {
    const bool opens = event == nlohmann::json::parse_event_t::object_start ||
                       event == nlohmann::json::parse_event_t::array_start;
    if (opens && depth >= kMaxJsonDepth)
      throw Error(file + ": invalid JSON: nested deeper than " + std::to_string(kMaxJsonDepth) + " levels");
    return true;
  };
  try {
    return nlohmann::json::parse(text, limitDepth);
  } catch (const nlohmann::json::exception& e) {  // syntax errors, and numbers that overflow a double
    std::string what = e.what();
    auto cut = what.find("] ");  // drop nlohmann's "[json.exception.parse_error.101] " tag
    throw Error(file + ": invalid JSON: " + excerpt(cut == std::string::npos ? what : what.substr(cut + 2), 160));
  }
}

JsonObject::JsonObject(const nlohmann::json& value, std::string pointer, std::string file)
    : value_(value), pointer_(std::move(pointer)), file_(std::move(file)) {
  if (!value_.is_object())
    throw Error(where(pointer_) + ": expected an object, got " + jsonTypeName(value_));
}

std::string JsonObject::pointer(const char* key) const { return pointer_ + "/" + excerpt(key); }

void JsonObject::fail(const char* key, const std::string& message) const {
  throw Error(where(pointer(key)) + ": " + message);
}

void JsonObject::expected(const char* key, const char* what, const nlohmann::json& got) const {
  std::string message = "expected ";
  message += what;
  message += ", got ";
  message += jsonTypeName(got);
  if (got.is_number()) message += ' ' + got.dump();
  fail(key, message);
}

const nlohmann::json* JsonObject::take(const char* key) {
  auto it = value_.find(key);
  if (it == value_.end()) return nullptr;
  used_.insert(key);
  return &*it;
}

const nlohmann::json* JsonObject::value(const char* key) { return take(key); }

void JsonObject::read(const char* key, double& out) {
  if (const auto* v = take(key)) {
    if (!v->is_number()) expected(key, "a number", *v);
    out = v->get<double>();
  }
}

void JsonObject::read(const char* key, float& out) {
  double d = out;
  read(key, d);
  if (std::abs(d) > double(std::numeric_limits<float>::max()))
    fail(key, "the number " + excerpt(std::to_string(d), 24) + " does not fit a 32-bit float");
  out = static_cast<float>(d);
}

void JsonObject::read(const char* key, std::uint32_t& out) {
  if (const auto* v = take(key)) {
    if (!v->is_number_integer() || (v->is_number_integer() && !v->is_number_unsigned()) ||
        v->get<std::uint64_t>() > 0xffffffffull)
      expected(key, "an integer in [0, 4294967295]", *v);
    out = static_cast<std::uint32_t>(v->get<std::uint64_t>());
  }
}

void JsonObject::read(const char* key, bool& out) {
  if (const auto* v = take(key)) {
    if (!v->is_boolean()) expected(key, "true or false", *v);
    out = v->get<bool>();
  }
}

void JsonObject::read(const char* key, std::string& out) {
  if (const auto* v = take(key)) {
    if (!v->is_string()) expected(key, "a string", *v);
    out = v->get<std::string>();
  }
}

void JsonObject::read(const char* key, glm::dvec3& out) {
  if (const auto* v = take(key)) {
    if (!v->is_array() || v->size() != 3) expected(key, "an array of 3 numbers", *v);
    for (int i = 0; i < 3; ++i) {
      if (!(*v)[i].is_number())
        throw Error(where(pointer(key) + "/" + std::to_string(i)) + ": expected a number, got " +
                    jsonTypeName((*v)[i]));
      out[i] = (*v)[i].get<double>();
    }
  }
}

void JsonObject::read(const char* key, glm::vec3& out) {
  glm::dvec3 d(out);
  read(key, d);
  for (int i = 0; i < 3; ++i)
    if (std::abs(d[i]) > double(std::numeric_limits<float>::max()))
      throw Error(where(pointer(key) + "/" + std::to_string(i)) + ": the number does not fit a 32-bit float");
  out = glm::vec3(d);
}

void JsonObject::readDegrees(const char* key, double& radians) {
  if (!has(key)) return;  // untouched default: no degree round trip to perturb it
  double degrees = 0.0;
  read(key, degrees);
  radians = glm::radians(degrees);
}

std::optional<JsonObject> JsonObject::object(const char* key) {
  const auto* v = take(key);
  if (!v) return std::nullopt;
  return JsonObject(*v, pointer(key), file_);
}

const nlohmann::json* JsonObject::array(const char* key) {
  const auto* v = take(key);
  if (v && !v->is_array()) expected(key, "an array", *v);
  return v;
}

void JsonObject::finish() const {
  for (const auto& [key, unused] : value_.items())
    if (!used_.count(key)) throw Error(where(pointer(key.c_str())) + ": unknown key");
}
}  // namespace hp
