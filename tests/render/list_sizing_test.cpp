// The growing tile lists' size policy (compute/raster/list_sizing.h), frame by frame on the CPU.
#include <gtest/gtest.h>

#include "compute/raster/list_sizing.h"

using hp::compute::ListSizing;

TEST(ListSizing, GrowsToTwiceTheNeedPastThreeQuartersAndNeverPastTheMaximum) {
  ListSizing sizing(1000, 100000, 10);
  EXPECT_EQ(sizing.next(3000, 4000), 0u);  // exactly 3/4: kept
  EXPECT_EQ(sizing.next(3001, 4000), 6002u);
  EXPECT_EQ(sizing.next(90000, 100000), 0u);  // at the maximum already
  EXPECT_EQ(sizing.next(80000, 99000), 100000u);
}

TEST(ListSizing, ShrinksOnlyAfterTheFramesInARowThatNeededUnderAQuarter) {
  ListSizing sizing(1000, 100000, 3);
  EXPECT_EQ(sizing.next(5000, 40000), 0u);
  EXPECT_EQ(sizing.next(7000, 40000), 0u);
  EXPECT_EQ(sizing.next(10000, 40000), 0u);  // a quarter exactly is not quiet: the count starts again
  EXPECT_EQ(sizing.next(6000, 40000), 0u);
  EXPECT_EQ(sizing.next(9000, 40000), 0u);
  EXPECT_EQ(sizing.next(4000, 40000), 18000u);  // twice the most of the three quiet frames
  EXPECT_EQ(sizing.next(4000, 18000), 0u);      // the count starts again for the new lists
}

TEST(ListSizing, AGrowingFrameRestartsTheQuietCount) {
  ListSizing sizing(1000, 100000, 2);
  EXPECT_EQ(sizing.next(100, 40000), 0u);
  EXPECT_EQ(sizing.next(35000, 40000), 70000u);
  EXPECT_EQ(sizing.next(100, 70000), 0u);
  EXPECT_EQ(sizing.next(100, 70000), 1000u);  // never below the floor
}

TEST(ListSizing, KeepsTheListsAtTheFloorOrWithoutShrinkFrames) {
  ListSizing atFloor(1000, 100000, 1);
  EXPECT_EQ(atFloor.next(0, 1000), 0u);
  EXPECT_EQ(atFloor.next(0, 1100), 1000u);
  ListSizing never(1000, 100000, 0);
  for (int frame = 0; frame < 1000; ++frame) ASSERT_EQ(never.next(0, 50000), 0u);
}
