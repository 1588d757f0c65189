// `--light SPEC`: split into the type and KEY=VALUE pairs, each key checked against its type before any
// value is read, then the light built through LightSpec's own constructors and validate().
#include "samples/tools/host/light_option.h"

#include <cmath>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

#include "engine/core/error.h"
#include "engine/core/hair/input_file.h"
#include "engine/core/hair/model_transform.h"

namespace hp {
namespace {
// Keys every light takes, then each type's own.
constexpr const char* kCommonKeys[] = {"color", "intensity", "shadows"};

std::vector<std::string_view> typeKeys(LightSpec::Type type) {
  switch (type) {
    case LightSpec::Type::Directional: return {"dir"};
    case LightSpec::Type::Spot: return {"pos", "target", "cone", "range"};
    case LightSpec::Type::Point: return {"pos", "range"};
  }
  return {};
}

std::string keyList(LightSpec::Type type) {
  std::string out;
  for (std::string_view k : typeKeys(type)) out += std::string(k) + ", ";
  for (const char* k : kCommonKeys) out += std::string(k) + ", ";
  return out.substr(0, out.size() - 2);
}

bool takesKey(LightSpec::Type type, std::string_view key) {
  for (std::string_view k : typeKeys(type))
    if (k == key) return true;
  for (const char* k : kCommonKeys)
    if (key == k) return true;
  return false;
}

std::vector<std::string_view> split(std::string_view text, char separator) {
  std::vector<std::string_view> parts;
  for (std::size_t start = 0;;) {
    const std::size_t end = text.find(separator, start);
    parts.push_back(text.substr(start, end == std::string_view::npos ? std::string_view::npos : end - start));
    if (end == std::string_view::npos) return parts;
    start = end + 1;
  }
}

LightSpec::Type parseType(std::string_view text) {
  if (text == "directional") return LightSpec::Type::Directional;
  if (text == "spot") return LightSpec::Type::Spot;
  if (text == "point") return LightSpec::Type::Point;
  throw Error("the light type must be directional, spot or point, got '" + excerpt(text) + "'");
}

// The KEY=VALUE pairs after the type, in a map: each key once, and only the type's own keys.
class Pairs {
 public:
  Pairs(LightSpec::Type type, const std::vector<std::string_view>& parts) {
    for (std::size_t i = 1; i < parts.size(); ++i) {
      const std::size_t eq = parts[i].find('=');
      if (eq == std::string_view::npos || eq == 0)
        throw Error("'" + excerpt(parts[i]) + "' is not KEY=VALUE");
      const std::string key(parts[i].substr(0, eq));
      if (!takesKey(type, key))
        throw Error("'" + excerpt(key) + "' is not a key of a " + lightTypeName(type) + " light (its keys: " +
                    keyList(type) + ")");
      if (!values_.emplace(key, parts[i].substr(eq + 1)).second) throw Error("'" + key + "' is given twice");
    }
  }

  bool has(const char* key) const { return values_.count(key) > 0; }
  [[noreturn]] void fail(const char* key, const std::string& why) const {
    throw Error(std::string(key) + "=" + excerpt(values_.at(key)) + ": " + why);
  }

  float number(const char* key) const { return numberIn(key, values_.at(key)); }

  glm::vec3 vec3(const char* key) const {
    const std::vector<std::string_view> parts = split(values_.at(key), ',');
    if (parts.size() != 3) fail(key, "expected X,Y,Z");
    return {numberIn(key, parts[0]), numberIn(key, parts[1]), numberIn(key, parts[2])};
  }

  // A position, target or direction: within head space, past which a length overflows (a direction of 1e30s
  // read as a zero vector).
  glm::vec3 place(const char* key) const {
    const glm::vec3 v = vec3(key);
    if (!withinHeadSpace(v)) fail(key, headSpaceRule());
    return v;
  }

  bool onOff(const char* key) const {
    const std::string& v = values_.at(key);
    if (v == "on" || v == "true") return true;
    if (v == "off" || v == "false") return false;
    fail(key, "expected on or off");
  }

 private:
  // The whole text must be one finite number: strtof alone accepts "nan", "inf" and a trailing rest.
  float numberIn(const char* key, std::string_view text) const {
    const std::string s(text);
    char* end = nullptr;
    const float v = s.empty() ? 0.0f : std::strtof(s.c_str(), &end);
    if (s.empty() || end != s.c_str() + s.size() || s.find_first_of(" \t") != std::string::npos)
      fail(key, "expected a number, got '" + excerpt(s) + "'");
    if (!std::isfinite(v)) fail(key, "must be a finite number");  // NaN, inf, or past the float range
    return v;
  }

  std::map<std::string, std::string> values_;
};

LightSpec directional(const Pairs& p) {
  LightSpec l;
  if (!p.has("dir")) return l;
  const glm::vec3 d = p.place("dir");
  if (!(glm::length(d) > 1e-6f) || !std::isfinite(glm::length(d))) p.fail("dir", "must be a non-zero vector");
  l.direction = glm::normalize(d);
  return l;
}

float rangeOf(const Pairs& p) {
  if (!p.has("range")) return 0.0f;
  const float range = p.number("range");
  if (!(range >= 0.0f)) p.fail("range", "must be >= 0 (0: no distance falloff)");
  return range;
}

glm::vec3 positionOf(const Pairs& p, LightSpec::Type type) {
  if (!p.has("pos")) throw Error(std::string("a ") + lightTypeName(type) + " light needs pos=X,Y,Z");
  return p.place("pos");
}

LightSpec spot(const Pairs& p, const glm::vec3& defaultTarget) {
  const glm::vec3 position = positionOf(p, LightSpec::Type::Spot);
  const glm::vec3 target = p.has("target") ? p.place("target") : defaultTarget;
  if (!(glm::length(position - target) > 1e-6f)) {
    if (p.has("target")) p.fail("target", "must differ from pos");
    p.fail("pos", "must differ from the spot's target (default: the camera target)");
  }
  const float cone = p.has("cone") ? p.number("cone") : 30.0f;
  if (!(cone > 0.0f && cone <= 80.0f)) p.fail("cone", "must be in (0, 80] degrees");
  LightSpec l = LightSpec::makeSpot(position, target, cone);
  l.range = rangeOf(p);
  return l;
}

// What every type takes: colour, intensity and the shadows switch.
void applyCommon(const Pairs& p, LightSpec& l) {
  if (p.has("color")) {
    l.color = p.vec3("color");
    if (!glm::all(glm::greaterThanEqual(l.color, glm::vec3(0.0f)))) p.fail("color", "components must be >= 0");
  }
  if (p.has("intensity")) {
    l.intensity = p.number("intensity");
    if (!(l.intensity >= 0.0f)) p.fail("intensity", "must be >= 0");
  }
  if (p.has("shadows")) l.shadows = p.onOff("shadows");
}
}  // namespace

LightSpec parseLightOption(std::string_view spec, const glm::vec3& defaultTarget) {
  const std::vector<std::string_view> parts = split(spec, ':');
  const LightSpec::Type type = parseType(parts[0]);
  const Pairs pairs(type, parts);
  LightSpec l;
  switch (type) {
    case LightSpec::Type::Directional: l = directional(pairs); break;
    case LightSpec::Type::Spot: l = spot(pairs, defaultTarget); break;
    case LightSpec::Type::Point: l = LightSpec::makePoint(positionOf(pairs, type), rangeOf(pairs)); break;
  }
  applyCommon(pairs, l);
  l.validate();
  return l;
}

const char* lightOptionSyntax() {
  return "directional[:dir=X,Y,Z] | spot:pos=X,Y,Z[:target=X,Y,Z][:cone=DEG][:range=R] | point:pos=X,Y,Z[:range=R], "
         "each with optional :color=R,G,B :intensity=I :shadows=on|off";
}
}  // namespace hp
