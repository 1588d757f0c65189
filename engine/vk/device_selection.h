#pragma once
// Contract: pure device-selection logic, testable without a GPU. Given what each physical device offers
// (DeviceCandidate) and a request (empty, an index, or a case-insensitive name substring), chooseDevice()
// returns the chosen index or an error, and for every device the reasons it was rejected.
// Without a request the best suitable device wins: discrete > integrated > virtual > CPU > other.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace hp::vk {
enum class DeviceKind { Discrete, Integrated, Virtual, Cpu, Other };
const char* deviceKindName(DeviceKind kind);

struct DeviceCandidate {
  std::uint32_t index = 0;
  std::string name;
  DeviceKind kind = DeviceKind::Other;
  std::uint32_t apiVersion = 0;
  // Filled by the probe: everything hairpipe needs that this device lacks, named
  // (e.g. "Vulkan 1.3", "feature synchronization2", "a graphics+compute queue").
  std::vector<std::string> missing;
};

struct DeviceRejection {
  std::uint32_t index;
  std::string name;
  std::string reason;
};

struct DeviceChoice {
  std::optional<std::uint32_t> chosen;  // index into the candidates' `index`
  std::vector<DeviceRejection> rejected;
  std::string error;                    // set when nothing was chosen: names the request and the devices
};

DeviceChoice chooseDevice(const std::vector<DeviceCandidate>& candidates, const std::string& request);
}  // namespace hp::vk
