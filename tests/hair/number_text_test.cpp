// The numbers error messages show (engine/core/number_text.h): whole numbers exactly, others short.
#include <gtest/gtest.h>

#include <limits>

#include "engine/core/number_text.h"

TEST(NumberText, WholeNumbersExactlyOthersInSixSignificantDigits) {
  EXPECT_EQ(hp::numberText(100000.0), "100000");
  EXPECT_EQ(hp::numberText(300000000.0), "300000000");  // a count read from a file, every digit
  EXPECT_EQ(hp::numberText(-2.0), "-2");
  EXPECT_EQ(hp::numberText(0.0), "0");
  EXPECT_EQ(hp::numberText(0.95), "0.95");
  EXPECT_EQ(hp::numberText(0.9f), "0.9");  // a float's widening error stays below six digits
  EXPECT_EQ(hp::numberText(1e-5), "1e-05");
  EXPECT_EQ(hp::numberText(1e30), "1e+30");
  EXPECT_EQ(hp::numberText(2.5e20), "2.5e+20");  // whole, but past what an int64 holds exactly
  EXPECT_EQ(hp::numberText(std::numeric_limits<double>::quiet_NaN()), "NaN");
  EXPECT_EQ(hp::numberText(std::numeric_limits<double>::infinity()), "Inf");
  EXPECT_EQ(hp::numberText(-std::numeric_limits<double>::infinity()), "-Inf");
}
