#pragma once
// Contract: base fixture of every test that touches Vulkan. It creates a headless context with the
// Khronos validation layer and synchronization validation on, and fails the test on any validation
// warning or error, including those reported while the device is destroyed. A missing device or
// layer fails SetUp (never a skip): CI always has lavapipe.
#include <gtest/gtest.h>

#include <memory>

#include "engine/vk/context.h"

namespace hp::test {
class VulkanTest : public ::testing::Test {
 protected:
  void SetUp() override;
  void TearDown() override;
  // Messages so far, then forget them (for tests that provoke validation on purpose).
  std::size_t takeValidationProblems();

  std::unique_ptr<vk::Context> ctx;
  std::shared_ptr<vk::ValidationLog> log;
};
}  // namespace hp::test
