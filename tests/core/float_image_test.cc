#include "core/float_image.h"

#include <gtest/gtest.h>

namespace novelty::core {
namespace {

TEST(FloatImage, ScalesSixteenBitsToTheEightBitRange) {
  EXPECT_FLOAT_EQ(ToFloat255(cv::Mat(1, 1, CV_16UC1, cv::Scalar(65535))).at<float>(0, 0), 255.0f);
  EXPECT_FLOAT_EQ(ToFloat255(cv::Mat(1, 1, CV_8UC1, cv::Scalar(200))).at<float>(0, 0), 200.0f);
  EXPECT_FLOAT_EQ(ToFloat255(cv::Mat(1, 1, CV_32FC1, cv::Scalar(3.5))).at<float>(0, 0), 3.5f);
  EXPECT_EQ(ToFloat255(cv::Mat::zeros(2, 2, CV_16UC3)).type(), CV_32FC3);
  EXPECT_THROW(ToFloat255(cv::Mat::zeros(2, 2, CV_64F)), std::invalid_argument);
}

TEST(FloatImage, ChannelMean) {
  EXPECT_FLOAT_EQ(ChannelMean(cv::Mat(1, 1, CV_8UC3, cv::Scalar(30, 60, 120))).at<float>(0, 0),
                  70.0f);
  EXPECT_EQ(ChannelMean(cv::Mat(1, 1, CV_8UC1, cv::Scalar(9))).type(), CV_32FC1);
}

}  // namespace
}  // namespace novelty::core
