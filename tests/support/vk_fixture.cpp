#include "tests/support/vk_fixture.h"

namespace hp::test {
void VulkanTest::SetUp() {
  vk::ContextOptions options;
  options.validation = true;
  options.appName = "hairpipe-tests";
  ASSERT_NO_THROW(ctx = vk::Context::createHeadless(options)) << "no Vulkan device with validation";
  log = ctx->sharedValidationLog();
}

void VulkanTest::TearDown() {
  ctx.reset();  // destroy first: leaked objects are reported at vkDestroyDevice
  if (log) {
    EXPECT_EQ(log->problemCount(), 0u) << "validation messages:\n" << log->describeProblems();
  }
}

std::size_t VulkanTest::takeValidationProblems() {
  std::size_t n = log->problemCount();
  log->clear();
  return n;
}
}  // namespace hp::test
