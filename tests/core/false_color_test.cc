#include "core/false_color.h"

#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace novelty::core {
namespace {

TEST(FalseColor, NaNIsGreyAndValuesAreClamped) {
  cv::Mat map(2, 2, CV_32FC1, cv::Scalar(0.0f));
  map.at<float>(0, 1) = std::nanf("");
  map.at<float>(1, 0) = 100.0f;  // beyond max: the top of the colour map
  map.at<float>(1, 1) = 10.0f;   // = max
  const cv::Mat rgb = FalseColor(map, 10.0);
  ASSERT_EQ(rgb.type(), CV_8UC3);
  EXPECT_EQ(rgb.at<cv::Vec3b>(0, 1), cv::Vec3b(60, 60, 60));
  EXPECT_EQ(rgb.at<cv::Vec3b>(1, 0), rgb.at<cv::Vec3b>(1, 1));
  EXPECT_NE(rgb.at<cv::Vec3b>(0, 0), rgb.at<cv::Vec3b>(1, 1));
}

}  // namespace
}  // namespace novelty::core
