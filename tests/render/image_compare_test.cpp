// compareImages reports what it measured or refuses: never a perfect score for an image it cannot measure;
// readPfm reads exactly what the header promises.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

#include "engine/core/error.h"
#include "samples/tools/image_compare.h"
#include "tests/support/refusal.h"
#include "samples/tools/linear_image.h"

namespace {
hp::LinearImage grey(float value) {
  hp::LinearImage im(8, 8, 3);
  for (float& v : im.values) v = value;
  return im;
}

// The message of compareImages' refusal, or "(accepted)".
std::string refusalOf(const hp::LinearImage& image, const hp::LinearImage& reference, float exposure = 1.0f) {
  return hp::test::refusalOf([&] { hp::compareImages(image, reference, {}, exposure); });
}

TEST(ImageCompare, IdenticalImagesScore99AndDifferentOnesLess) {
  const hp::ImageComparison same = hp::compareImages(grey(0.3f), grey(0.3f), {}, 1.0f);
  EXPECT_EQ(same.psnrDb, 99.0);
  EXPECT_NEAR(same.ssim, 1.0, 1e-12);
  const hp::ImageComparison other = hp::compareImages(grey(0.3f), grey(0.4f), {}, 1.0f);
  EXPECT_LT(other.psnrDb, 40.0);
  EXPECT_NEAR(other.luminanceRatio, 0.75, 1e-6);
}

TEST(ImageCompare, NonFiniteAndHugeValuesAndBadExposuresAreRefusedByName) {
  hp::LinearImage nan = grey(0.3f);
  nan.at(2, 5, 1) = std::numeric_limits<float>::quiet_NaN();
  EXPECT_NE(refusalOf(nan, grey(0.3f)).find("the image has a non-finite value at pixel (2, 5), channel 1"), std::string::npos)
      << refusalOf(nan, grey(0.3f));
  hp::LinearImage inf = grey(0.3f);
  inf.at(0, 0, 0) = std::numeric_limits<float>::infinity();
  EXPECT_NE(refusalOf(grey(0.3f), inf).find("the reference has a non-finite value"), std::string::npos);
  EXPECT_NE(refusalOf(grey(2.4e23f), grey(0.3f)).find("came out non-finite"), std::string::npos);
  EXPECT_NE(refusalOf(grey(-1e30f), grey(0.3f)).find("came out non-finite"), std::string::npos);
  // Rounding's small negatives (real-time frames hold a few) are measured, not refused.
  hp::LinearImage rounded = grey(0.3f);
  rounded.at(7, 7, 2) = -5e-4f;
  EXPECT_LT(hp::compareImages(rounded, grey(0.3f), {}, 1.0f).psnrDb, 99.0);
  for (float exposure : {std::numeric_limits<float>::quiet_NaN(), -1.0f, 0.0f})
    EXPECT_NE(refusalOf(grey(0.3f), grey(0.3f), exposure).find("exposure must be finite and > 0"), std::string::npos)
        << exposure;
}
}  // namespace

namespace {
// The message of readPfm's refusal of these bytes, or "(accepted)".
std::string pfmRefusal(const std::string& bytes) {
  const std::filesystem::path path = std::filesystem::temp_directory_path() / "hairpipe_pfm_reader_test.pfm";
  { std::ofstream(path, std::ios::binary) << bytes; }
  const std::string message = hp::test::refusalOf([&] { hp::readPfm(path); });
  std::filesystem::remove(path);
  return message;
}

TEST(PfmReader, RoundTripsAndRefusesHeadersThatPromiseOtherData) {
  const std::filesystem::path path = std::filesystem::temp_directory_path() / "hairpipe_pfm_round_trip.pfm";
  hp::LinearImage image = grey(0.25f);
  image.at(3, 1, 2) = 7.5f;
  hp::writePfm(path, image);
  EXPECT_EQ(hp::readPfm(path).values, image.values);
  std::filesystem::remove(path);
  // A 40-byte file whose header promises 16384 x 16384 pixels: refused by the sizes, before any allocation.
  const std::string huge = "PF\n16384 16384\n-1.0\n" + std::string(20, 'x');
  EXPECT_NE(pfmRefusal(huge).find("need 3221225472 bytes after the header, the file has 20"), std::string::npos)
      << pfmRefusal(huge);
  // 96 bytes of header text only, with the scale at the very end: its text must not be read as pixels.
  const std::string headerOnly = "Pf" + std::string(87, ' ') + "24 1 -1";
  ASSERT_EQ(headerOnly.size(), 96u);
  EXPECT_NE(pfmRefusal(headerOnly).find("must end with one whitespace character"), std::string::npos)
      << pfmRefusal(headerOnly);
  // The byte after the scale is data's first unless it is whitespace.
  EXPECT_NE(pfmRefusal("Pf 1 1 -1x" + std::string(4, '\0')).find("must end with one whitespace character"),
            std::string::npos);
}
}  // namespace
