// The process's cache of costly pure results (engine/core/recent_cache.h): made once per key, the least
// recently made dropped past the capacity, nothing kept when making throws.
#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>

#include "engine/core/recent_cache.h"

TEST(RecentCache, MakesOncePerKeyAndDropsTheOldestPastItsCapacity) {
  hp::RecentCache<int, int, 2> cache;
  int made = 0;
  auto square = [&](int k) { return cache.get(k, [&] { ++made; return k * k; }); };
  const auto nine = square(3);
  EXPECT_EQ(*nine, 9);
  EXPECT_EQ(square(3), nine);  // the same value, not made again
  EXPECT_EQ(made, 1);
  square(4);
  square(5);  // 3 is now the oldest of three: dropped
  EXPECT_EQ(made, 3);
  EXPECT_EQ(*square(5), 25);
  EXPECT_EQ(made, 3);
  EXPECT_EQ(*square(3), 9);
  EXPECT_EQ(made, 4);
  EXPECT_EQ(*nine, 9);  // a value handed out outlives its entry
}

// A value made while another make() of the same key ran (here nested in it; across threads, the same race)
// is the one kept, and the later finisher returns it rather than keeping a second entry.
TEST(RecentCache, TheFirstValueKeptForAKeyWinsOverALaterFinisher) {
  hp::RecentCache<int, int, 2> cache;
  std::shared_ptr<const int> inner;
  const auto outer = cache.get(1, [&] {
    inner = cache.get(1, [] { return 2; });
    return 3;
  });
  EXPECT_EQ(outer, inner);
  EXPECT_EQ(*outer, 2);
  cache.get(2, [] { return 4; });  // with a duplicate entry for 1 this would drop the first of them only
  EXPECT_EQ(*cache.get(1, [] { return 5; }), 2) << "the key's entry was pushed out by its own duplicate";
}

TEST(RecentCache, AMakeThatThrowsKeepsNothing) {
  hp::RecentCache<int, int, 2> cache;
  EXPECT_THROW(cache.get(1, []() -> int { throw std::runtime_error("no"); }), std::runtime_error);
  EXPECT_EQ(*cache.get(1, [] { return 7; }), 7);
}
