#pragma once
// Contract: typed reads from one JSON object of a config file, with errors that name the file and
// the JSON pointer of the offending value ("scene.json: /simulation/dt: expected a number, got
// string"). Reads are optional: an absent key leaves the output unchanged (the default stands).
// finish() rejects every key that no read asked for, so typos never pass silently.
#include <nlohmann/json.hpp>

#include <glm/glm.hpp>

#include <cstdint>
#include <optional>
#include <set>
#include <string>

namespace hp {
class JsonObject {
 public:
  // Throws unless `value` is an object.
  JsonObject(const nlohmann::json& value, std::string pointer, std::string file);

  bool has(const char* key) const { return value_.contains(key); }
  void read(const char* key, double& out);
  void read(const char* key, float& out);
  void read(const char* key, std::uint32_t& out);
  void read(const char* key, bool& out);
  void read(const char* key, std::string& out);
  void read(const char* key, glm::vec3& out);
  void read(const char* key, glm::dvec3& out);
  // An angle given in degrees, stored in radians.
  void readDegrees(const char* key, double& radians);
  std::optional<JsonObject> object(const char* key);
  const nlohmann::json* array(const char* key);  // nullptr when absent; throws if not an array
  const nlohmann::json* value(const char* key);  // any type; marks the key as read

  std::string pointer(const char* key) const;  // keys are quoted as a short excerpt
  std::string where(const std::string& pointer) const { return file_ + ": " + (pointer.empty() ? "/" : pointer); }
  std::string here() const { return where(pointer_); }  // the object's own place: "file: /fibre/material"
  [[noreturn]] void fail(const char* key, const std::string& message) const;
  void finish() const;  // throws on the first key no read asked for
  const std::string& file() const { return file_; }

 private:
  const nlohmann::json* take(const char* key);
  [[noreturn]] void expected(const char* key, const char* what, const nlohmann::json& got) const;

  const nlohmann::json& value_;
  std::string pointer_;
  std::string file_;
  std::set<std::string> used_;
};

// How deep objects and arrays may nest in a config file (a scene needs 3 levels).
inline constexpr int kMaxJsonDepth = 32;
// Parses JSON text; a syntax error, a number that overflows a double or nesting deeper than
// kMaxJsonDepth becomes hp::Error "file: invalid JSON: <where and why>" (quoting a short excerpt).
nlohmann::json parseJsonText(const std::string& text, const std::string& file);
// What a JSON value is, for messages: "number", "string", "array", ...
std::string jsonTypeName(const nlohmann::json& value);
}  // namespace hp
