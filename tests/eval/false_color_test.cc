#include "eval/false_color.h"

#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace novelty::eval {
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

// Images in a row with a gap; with captions, a strip above them holds text over each image.
TEST(SideBySide, PlacesImagesAndCaptions) {
  const cv::Mat a(10, 20, CV_8UC3, cv::Scalar(200, 0, 0)),
      b(10, 30, CV_8UC3, cv::Scalar(0, 200, 0));
  const cv::Mat plain = SideBySide({a, b}, 4);
  EXPECT_EQ(plain.size(), cv::Size(20 + 4 + 30, 10));
  EXPECT_EQ(plain.at<cv::Vec3b>(5, 30), cv::Vec3b(0, 200, 0));
  const cv::Mat captioned = SideBySide({a, b}, 4, {"camera", "surprise"});
  EXPECT_EQ(captioned.size(), cv::Size(54, 10 + 16));
  EXPECT_EQ(captioned.at<cv::Vec3b>(16 + 5, 30), cv::Vec3b(0, 200, 0));  // images below the strip
  // Text was drawn in the strip above each image (bright pixels on the dark background).
  cv::Mat grey;
  cv::cvtColor(captioned(cv::Rect(0, 0, 54, 16)), grey, cv::COLOR_RGB2GRAY);
  EXPECT_GT(cv::countNonZero(grey(cv::Rect(0, 0, 20, 16)) > 120), 5);
  EXPECT_GT(cv::countNonZero(grey(cv::Rect(24, 0, 30, 16)) > 120), 5);
  EXPECT_THROW(SideBySide({a, b}, 4, {"one"}), std::invalid_argument);
}

}  // namespace
}  // namespace novelty::eval
