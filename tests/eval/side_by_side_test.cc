#include "eval/side_by_side.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace novelty::eval {
namespace {

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
