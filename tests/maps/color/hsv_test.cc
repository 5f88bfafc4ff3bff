#include "maps/color/hsv.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <stdexcept>

namespace novelty::color {
namespace {

// Textbook RGB → HSV (Smith 1978), independent of OpenCV, for comparison.
cv::Vec3f ReferenceHsv(float r, float g, float b) {
  const float mx = std::max({r, g, b}), mn = std::min({r, g, b}), c = mx - mn;
  float h = 0.0f;
  if (c > 0.0f) {
    if (mx == r)
      h = 60.0f * std::fmod((g - b) / c + 6.0f, 6.0f);
    else if (mx == g)
      h = 60.0f * ((b - r) / c + 2.0f);
    else
      h = 60.0f * ((r - g) / c + 4.0f);
  }
  return {h, mx > 0.0f ? c / mx : 0.0f, mx};
}

TEST(Hsv, PrimariesAndGreys) {
  cv::Mat rgb(1, 5, CV_8UC3);
  rgb.at<cv::Vec3b>(0) = {255, 0, 0};
  rgb.at<cv::Vec3b>(1) = {0, 255, 0};
  rgb.at<cv::Vec3b>(2) = {0, 0, 255};
  rgb.at<cv::Vec3b>(3) = {128, 128, 128};
  rgb.at<cv::Vec3b>(4) = {0, 0, 0};
  const cv::Mat hsv = RgbToHsv(rgb);
  const float expected[5][3] = {{0, 1, 255}, {120, 1, 255}, {240, 1, 255}, {0, 0, 128}, {0, 0, 0}};
  for (int i = 0; i < 5; ++i)
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(hsv.at<cv::Vec3f>(i)[k], expected[i][k], 1e-3f);
}

TEST(Hsv, MatchesTextbookFormulaOnRandomColours) {
  std::mt19937 rng(1);
  std::uniform_int_distribution<int> d(0, 255);
  cv::Mat rgb(100, 100, CV_8UC3);
  for (int i = 0; i < rgb.rows * rgb.cols; ++i)
    rgb.at<cv::Vec3b>(i) = cv::Vec3b(d(rng), d(rng), d(rng));
  const cv::Mat hsv = RgbToHsv(rgb);
  for (int i = 0; i < rgb.rows * rgb.cols; ++i) {
    const cv::Vec3b c = rgb.at<cv::Vec3b>(i);
    const cv::Vec3f ref = ReferenceHsv(c[0], c[1], c[2]);
    const cv::Vec3f got = hsv.at<cv::Vec3f>(i);
    const float dh = std::abs(got[0] - ref[0]);
    EXPECT_LT(std::min(dh, 360.0f - dh), 0.05f) << "rgb " << c;
    EXPECT_NEAR(got[1], ref[1], 1e-5f) << "rgb " << c;
    EXPECT_NEAR(got[2], ref[2], 1e-4f) << "rgb " << c;
  }
}

TEST(Hsv, WrongImageTypeIsRejected) {
  EXPECT_THROW(RgbToHsv(cv::Mat(2, 2, CV_16UC3)), std::invalid_argument);
}

}  // namespace
}  // namespace novelty::color
