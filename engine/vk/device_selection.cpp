#include "engine/vk/device_selection.h"

#include <algorithm>
#include <cctype>

namespace hp::vk {
namespace {
int preference(DeviceKind kind) {
  switch (kind) {
    case DeviceKind::Discrete: return 0;
    case DeviceKind::Integrated: return 1;
    case DeviceKind::Virtual: return 2;
    case DeviceKind::Cpu: return 3;
    case DeviceKind::Other: return 4;
  }
  return 5;
}

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

bool isIndex(const std::string& s) {
  return !s.empty() && s.size() < 6 && std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isdigit(c); });
}

std::string joinMissing(const std::vector<std::string>& missing) {
  std::string out = "missing ";
  for (std::size_t i = 0; i < missing.size(); ++i) out += (i ? ", " : "") + missing[i];
  return out;
}

std::string listDevices(const std::vector<DeviceCandidate>& candidates) {
  if (candidates.empty()) return "no Vulkan devices were found";
  std::string out = "available devices:";
  for (const auto& c : candidates)
    out += "\n  [" + std::to_string(c.index) + "] " + c.name + " (" + deviceKindName(c.kind) + ")" +
           (c.missing.empty() ? "" : " — unsuitable: " + joinMissing(c.missing));
  return out;
}

bool matches(const DeviceCandidate& c, const std::string& request) {
  if (isIndex(request)) return c.index == static_cast<std::uint32_t>(std::stoul(request));
  return lower(c.name).find(lower(request)) != std::string::npos;
}
}  // namespace

const char* deviceKindName(DeviceKind kind) {
  switch (kind) {
    case DeviceKind::Discrete: return "discrete GPU";
    case DeviceKind::Integrated: return "integrated GPU";
    case DeviceKind::Virtual: return "virtual GPU";
    case DeviceKind::Cpu: return "CPU";
    case DeviceKind::Other: return "other";
  }
  return "unknown";
}

DeviceChoice chooseDevice(const std::vector<DeviceCandidate>& candidates, const std::string& request) {
  DeviceChoice choice;
  const DeviceCandidate* best = nullptr;
  for (const auto& c : candidates) {
    if (!request.empty() && !matches(c, request)) {
      choice.rejected.push_back({c.index, c.name, "does not match --device '" + request + "'"});
      continue;
    }
    if (!c.missing.empty()) {
      choice.rejected.push_back({c.index, c.name, joinMissing(c.missing)});
      continue;
    }
    if (!best || preference(c.kind) < preference(best->kind)) {
      if (best) choice.rejected.push_back({best->index, best->name, "a preferred device type was found"});
      best = &c;
    } else {
      choice.rejected.push_back({c.index, c.name, "a preferred device type was found"});
    }
  }
  if (best) {
    choice.chosen = best->index;
    return choice;
  }
  choice.error = request.empty() ? "no suitable Vulkan device" : "no suitable Vulkan device matches '" + request + "'";
  choice.error += "; " + listDevices(candidates);
  return choice;
}
}  // namespace hp::vk
