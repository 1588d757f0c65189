#pragma once
// Contract: the hp::Error check() throws for VK_ERROR_DEVICE_LOST ("vkQueueSubmit2 failed:
// VK_ERROR_DEVICE_LOST (-4)"). Everyone else sees an hp::Error like any other failure; a caller able to
// start again on a new device (the viewer) tells it apart by type.
#include "engine/error.h"

namespace hp::vk {
class DeviceLost : public Error {
 public:
  using Error::Error;
};
}  // namespace hp::vk
