#include "core/depth_check.h"

#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>

namespace novelty::core {
namespace {

TEST(DepthCheck, CountsNegativeAndInfiniteDepthsButNotUnknownOnes) {
  cv::Mat depth(3, 4, CV_32FC1, cv::Scalar(1.5));
  EXPECT_EQ(CountBrokenDepths(depth), 0);
  depth.at<float>(0, 0) = 0.0f;                                     // unknown
  depth.at<float>(0, 1) = std::numeric_limits<float>::quiet_NaN();  // unknown
  depth.at<float>(1, 2) = -0.001f;                                  // broken
  depth.at<float>(2, 3) = std::numeric_limits<float>::infinity();   // broken
  depth.at<float>(2, 0) = -std::numeric_limits<float>::infinity();  // broken
  EXPECT_EQ(CountBrokenDepths(depth), 3);
  EXPECT_EQ(CountBrokenDepths(depth(cv::Rect(0, 0, 2, 3))), 1);  // a view, row by row
  EXPECT_THROW(CountBrokenDepths(cv::Mat(2, 2, CV_16UC1)), std::invalid_argument);
}

}  // namespace
}  // namespace novelty::core
