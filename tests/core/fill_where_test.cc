#include "core/fill_where.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace novelty::core {
namespace {

// Every fast-path type and one that falls back (CV_16UC3), whole images and views into larger
// ones: the same as OpenCV's masked setTo, element for element.
TEST(FillWhere, EqualsMaskedSetTo) {
  cv::RNG rng(7);
  for (int type : {CV_32FC1, CV_8UC1, CV_8UC2, CV_8UC3, CV_8UC4, CV_16UC3}) {
    for (bool view : {false, true}) {
      cv::Mat whole(30, 45, type), mask_whole(30, 45, CV_8UC1);
      rng.fill(whole, cv::RNG::UNIFORM, 0, 200);
      rng.fill(mask_whole, cv::RNG::UNIFORM, 0, 3);  // 0, 1 or 2: any non-zero value counts
      const cv::Rect r = view ? cv::Rect(3, 2, 37, 25) : cv::Rect(0, 0, 45, 30);
      cv::Mat m = whole(r).clone(), expected = whole(r).clone();
      if (view) m = whole(r);
      const cv::Mat mask = mask_whole(r);
      const cv::Scalar value(250, 17, 3, 99);
      FillWhere(m, mask, value);
      expected.setTo(value, mask);
      EXPECT_EQ(cv::norm(m, expected, cv::NORM_INF), 0.0) << "type " << type << " view " << view;
      EXPECT_GT(cv::countNonZero(mask), 200);
      EXPECT_LT(cv::countNonZero(mask), int(mask.total()) - 200);
    }
  }
}

TEST(FillWhere, NaNIsWrittenWhereMaskedAndKeptElsewhere) {
  cv::Mat m(4, 20, CV_32FC1, cv::Scalar(2.5f)), mask = cv::Mat::zeros(4, 20, CV_8UC1);
  m.at<float>(1, 3) = std::numeric_limits<float>::quiet_NaN();  // unmasked NaN stays
  mask.at<uchar>(2, 17) = 255;
  FillWhere(m, mask, cv::Scalar::all(std::numeric_limits<float>::quiet_NaN()));
  EXPECT_TRUE(std::isnan(m.at<float>(2, 17)));
  EXPECT_TRUE(std::isnan(m.at<float>(1, 3)));
  EXPECT_EQ(cv::countNonZero(m == m), 78);  // NaN ≠ NaN: two of 80
}

TEST(FillWhere, AMaskThatDoesNotFitIsRejected) {
  cv::Mat m(4, 20, CV_32FC1, cv::Scalar(1));
  EXPECT_THROW(FillWhere(m, cv::Mat::zeros(4, 19, CV_8UC1), cv::Scalar(0)), std::invalid_argument);
  EXPECT_THROW(FillWhere(m, cv::Mat::zeros(4, 20, CV_32FC1), cv::Scalar(0)), std::invalid_argument);
  EXPECT_EQ(m.at<float>(3, 19), 1.0f);
}

}  // namespace
}  // namespace novelty::core
