#include "core/nearest_pixel.h"

#include <gtest/gtest.h>

#include <limits>

namespace novelty::core {
namespace {

const cv::Size kSize(320, 240);

TEST(NearestPixel, RoundsToTheNearestPixel) {
  EXPECT_EQ(NearestPixel({10.49f, 20.51f}, kSize), cv::Point(10, 21));
  EXPECT_EQ(NearestPixel({10.5f, 0.0f}, kSize), cv::Point(11, 0));  // half away from zero
  EXPECT_EQ(NearestPixel({319.0f, 239.0f}, kSize), cv::Point(319, 239));
}

TEST(NearestPixel, ACentreLessThanAPixelOutsideIsTheBorderPixel) {
  // 319.7 rounds to 320, one past the last column; the lookup must not read outside.
  EXPECT_EQ(NearestPixel({319.7f, 239.6f}, kSize), cv::Point(319, 239));
  EXPECT_EQ(NearestPixel({-0.6f, -0.99f}, kSize), cv::Point(0, 0));
}

TEST(NearestPixel, FartherOutOrNotFiniteIsNone) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_FALSE(NearestPixel({320.0f, 5.0f}, kSize));
  EXPECT_FALSE(NearestPixel({5.0f, 240.0f}, kSize));
  EXPECT_FALSE(NearestPixel({-1.0f, 5.0f}, kSize));
  EXPECT_FALSE(NearestPixel({5.0f, -1e20f}, kSize));  // would overflow int if rounded
  EXPECT_FALSE(NearestPixel({nan, 5.0f}, kSize));
  EXPECT_FALSE(NearestPixel({5.0f, std::numeric_limits<float>::infinity()}, kSize));
  EXPECT_FALSE(NearestPixel({5.0f, 5.0f}, cv::Size()));  // an empty image has no pixel
  EXPECT_FALSE(NearestPixel({-0.5f, -0.5f}, cv::Size()));  // not even within a pixel of it
}

}  // namespace
}  // namespace novelty::core
