// The strand buffers' total size against the device's memory: chunking keeps descriptor ranges legal,
// this keeps the whole allocation possible. Pure arithmetic, no device.
#include <gtest/gtest.h>

#include "compute/strands/strand_buffers.h"
#include "engine/core/error.h"

using namespace hp;

TEST(StrandMemory, OneMillionStrandsFitTwoGigabytesAndTwoMillionDoNot) {
  const VkDeviceSize heap = 2048ull << 20;  // lavapipe's reported device-local heap
  const VkDeviceSize limit = 128ull << 20;
  EXPECT_NO_THROW(compute::checkStrandMemory(compute::planStrandLayout(3000, 7, 6000, 1000000, {}, limit), heap));
  try {
    compute::checkStrandMemory(compute::planStrandLayout(3000, 7, 6000, 2000000, {}, limit), heap);
    FAIL() << "accepted 2M strands in 2 GiB";
  } catch (const hp::Error& e) {
    EXPECT_NE(std::string(e.what()).find("2000000 strands"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("2048 MiB device-local heap"), std::string::npos) << e.what();
  }
}
