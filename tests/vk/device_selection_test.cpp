// Pure selection logic on made-up devices: no GPU involved.
#include <gtest/gtest.h>

#include "engine/vk/device_selection.h"

using hp::vk::chooseDevice;
using hp::vk::DeviceCandidate;
using hp::vk::DeviceKind;

namespace {
std::vector<DeviceCandidate> fleet() {
  return {
      {0, "llvmpipe (LLVM 15)", DeviceKind::Cpu, 0, {}},
      {1, "Intel UHD 630", DeviceKind::Integrated, 0, {}},
      {2, "NVIDIA H100", DeviceKind::Discrete, 0, {}},
      {3, "Old GPU", DeviceKind::Discrete, 0, {"Vulkan 1.3"}},
  };
}
}  // namespace

TEST(DeviceSelection, PrefersDiscreteOverIntegratedOverCpu) {
  auto choice = chooseDevice(fleet(), "");
  ASSERT_TRUE(choice.chosen);
  EXPECT_EQ(*choice.chosen, 2u);
  auto noDiscrete = fleet();
  noDiscrete.erase(noDiscrete.begin() + 2);
  EXPECT_EQ(*chooseDevice(noDiscrete, "").chosen, 1u);
}

TEST(DeviceSelection, RejectedDevicesCarryTheirReasons) {
  auto choice = chooseDevice(fleet(), "");
  bool sawMissing = false;
  for (const auto& r : choice.rejected)
    if (r.index == 3) {
      sawMissing = true;
      EXPECT_NE(r.reason.find("Vulkan 1.3"), std::string::npos) << r.reason;
    }
  EXPECT_TRUE(sawMissing);
  EXPECT_EQ(choice.rejected.size(), 3u);
}

TEST(DeviceSelection, ByIndexAndByCaseInsensitiveName) {
  EXPECT_EQ(*chooseDevice(fleet(), "0").chosen, 0u);
  EXPECT_EQ(*chooseDevice(fleet(), "LLVMpipe").chosen, 0u);
  EXPECT_EQ(*chooseDevice(fleet(), "intel").chosen, 1u);
}

TEST(DeviceSelection, UnsuitableRequestedDeviceIsAnErrorWithReasons) {
  auto choice = chooseDevice(fleet(), "old gpu");
  EXPECT_FALSE(choice.chosen);
  EXPECT_NE(choice.error.find("Old GPU"), std::string::npos) << choice.error;
  EXPECT_NE(choice.error.find("Vulkan 1.3"), std::string::npos) << choice.error;
}

TEST(DeviceSelection, NoMatchListsEveryDevice) {
  auto choice = chooseDevice(fleet(), "nosuchdevice");
  ASSERT_FALSE(choice.chosen);
  for (const char* name : {"llvmpipe", "Intel UHD 630", "NVIDIA H100", "Old GPU"})
    EXPECT_NE(choice.error.find(name), std::string::npos) << choice.error;
  EXPECT_FALSE(chooseDevice({}, "").chosen);
  EXPECT_NE(chooseDevice({}, "").error.find("no Vulkan devices"), std::string::npos);
}
