// `hairpipe info [--json] [--device D]`: every Vulkan device, the one hairpipe would select, and
// whether the validation layer is available; the library's build identity and its disk cache (HAIRPIPE_CACHE_DIR).
#include <cstdlib>
#include <iostream>

#include <nlohmann/json.hpp>

#include "engine/core/build_identity.h"
#include "engine/core/disk_cache.h"
#include "engine/core/error.h"
#include "engine/vk/context.h"
#include "engine/vk/device_probe.h"
#include "samples/cli/command.h"
#include "samples/tools/host/json_text.h"

namespace hp::cli::cmd_info {  // per subcommand: file-local names stay apart in a unity build

namespace {
struct InfoOptions {
  bool json = false;
  std::string device;
};

std::string versionString(std::uint32_t v) {
  return std::to_string(VK_API_VERSION_MAJOR(v)) + "." + std::to_string(VK_API_VERSION_MINOR(v)) + "." +
         std::to_string(VK_API_VERSION_PATCH(v));
}

nlohmann::json deviceJson(const hp::vk::DeviceReport& d) {
  const auto& limits = d.properties.limits;
  nlohmann::json heaps = nlohmann::json::array();
  for (std::uint32_t i = 0; i < d.memory.memoryHeapCount; ++i)
    heaps.push_back({{"size_mib", d.memory.memoryHeaps[i].size >> 20},
                     {"device_local", bool(d.memory.memoryHeaps[i].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT)}});
  return {{"index", d.candidate.index},
          {"name", d.candidate.name},
          {"type", hp::vk::deviceKindName(d.candidate.kind)},
          {"driver_name", d.driver.driverName},
          {"driver_info", d.driver.driverInfo},
          {"driver_version", d.properties.driverVersion},
          {"api_version", versionString(d.properties.apiVersion)},
          {"heaps", heaps},
          {"max_storage_buffer_range", limits.maxStorageBufferRange},
          {"max_compute_workgroup_invocations", limits.maxComputeWorkGroupInvocations},
          {"timestamp_period_ns", limits.timestampPeriod},
          {"timestamps", d.timestamps},
          {"suitable", d.candidate.missing.empty()},
          {"missing", d.candidate.missing}};
}

void printText(const nlohmann::json& report) {
  std::cout << "Vulkan loader " << report["loader_version"].get<std::string>() << ", validation layer "
            << (report["validation_layer"].get<bool>() ? "available" : "NOT available") << "\n"
            << "hairpipe build " << report["build_identity"].get<std::string>() << ", disk cache "
            << (report["disk_cache"].is_null() ? "off (HAIRPIPE_CACHE_DIR unset)" : report["disk_cache"].get<std::string>())
            << "\n";
  for (const auto& d : report["devices"]) {
    std::cout << "[" << d["index"] << "] " << d["name"].get<std::string>() << " (" << d["type"].get<std::string>()
              << ")" << (d["index"] == report["selected"] ? "  <- selected" : "") << "\n"
              << "    driver " << d["driver_name"].get<std::string>() << " " << d["driver_info"].get<std::string>()
              << ", Vulkan " << d["api_version"].get<std::string>() << "\n"
              << "    maxStorageBufferRange " << d["max_storage_buffer_range"] << ", maxComputeWorkGroupInvocations "
              << d["max_compute_workgroup_invocations"] << ", timestampPeriod " << d["timestamp_period_ns"]
              << " ns\n    heaps:";
    for (const auto& h : d["heaps"])
      std::cout << " " << h["size_mib"] << " MiB" << (h["device_local"].get<bool>() ? " (device-local)" : "");
    std::cout << "\n";
    if (!d["suitable"].get<bool>()) {
      std::cout << "    unsuitable, missing:";
      for (const auto& m : d["missing"]) std::cout << " " << m.get<std::string>() << ";";
      std::cout << "\n";
    }
  }
}

void runInfo(const InfoOptions& opt) {
  hp::vk::InstanceProbe probe;
  std::vector<hp::vk::DeviceCandidate> candidates;
  nlohmann::json devices = nlohmann::json::array();
  for (const auto& d : probe.devices()) {
    candidates.push_back(d.candidate);
    devices.push_back(deviceJson(d));
  }
  std::string request = opt.device;
  if (request.empty() && std::getenv("HAIRPIPE_DEVICE")) request = std::getenv("HAIRPIPE_DEVICE");
  hp::vk::DeviceChoice choice = hp::vk::chooseDevice(candidates, request);
  if (!choice.chosen) throw hp::Error(choice.error);
  const hp::DiskCache& cache = hp::DiskCache::process();
  nlohmann::json report = {{"loader_version", versionString(probe.loaderVersion())},
                           {"validation_layer", hp::vk::instanceLayerAvailable("VK_LAYER_KHRONOS_validation")},
                           {"build_identity", hp::buildIdentity()},
                           {"disk_cache", cache.enabled() ? nlohmann::json(cache.folder().string()) : nlohmann::json()},
                           {"selected", *choice.chosen},
                           {"devices", devices}};
  if (opt.json)
    std::cout << hp::jsonText(report) << "\n";
  else
    printText(report);
}

void setupInfo(CLI::App& app) {
  auto opt = std::make_shared<InfoOptions>();
  CLI::App* cmd = app.add_subcommand("info", "List Vulkan devices, the one hairpipe selects, and validation support");
  cmd->add_flag("--json", opt->json, "Print JSON instead of text");
  cmd->add_option("--device", opt->device, "Device to select: index or case-insensitive name substring (env HAIRPIPE_DEVICE)");
  cmd->callback([opt] { runInfo(*opt); });
}
}  // namespace

HP_CLI_COMMAND(setupInfo);
}  // namespace hp::cli::cmd_info
