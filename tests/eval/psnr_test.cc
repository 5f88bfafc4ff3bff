#include "eval/psnr.h"

#include <gtest/gtest.h>

#include <cmath>

namespace novelty::eval {
namespace {

TEST(Psnr, KnownMeanSquaredError) {
  const cv::Mat a(4, 4, CV_8UC3, cv::Scalar(100, 100, 100));
  const cv::Mat b(4, 4, CV_8UC3, cv::Scalar(110, 100, 90));  // MSE = (100 + 0 + 100) / 3
  EXPECT_NEAR(Psnr(a, b), 10 * std::log10(255.0 * 255.0 / (200.0 / 3)), 1e-12);
  EXPECT_TRUE(std::isinf(Psnr(a, a)));
}

TEST(Psnr, OnlyMaskedPixelsCount) {
  cv::Mat a(2, 2, CV_8UC1, cv::Scalar(50)), b = a.clone();
  b.at<uint8_t>(0, 0) = 250;  // masked out
  b.at<uint8_t>(1, 1) = 60;   // counted: MSE = 100 / 2
  cv::Mat mask(2, 2, CV_8UC1, cv::Scalar(255));
  mask.at<uint8_t>(0, 0) = 0;
  mask.at<uint8_t>(0, 1) = 0;
  EXPECT_NEAR(Psnr(a, b, mask), 10 * std::log10(255.0 * 255.0 / 50.0), 1e-12);
  EXPECT_TRUE(std::isnan(Psnr(a, b, cv::Mat::zeros(2, 2, CV_8UC1))));
  EXPECT_THROW(Psnr(a, cv::Mat(3, 2, CV_8UC1)), std::invalid_argument);
}

}  // namespace
}  // namespace novelty::eval
