#include "maps/color/ycbcr_planes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

#include "maps/color/ycbcr.h"

namespace novelty::color {
namespace {

// 256 rows × 261 columns (sixteen-pixel groups and a tail) covering every value per channel.
cv::Mat TestImage() {
  cv::Mat rgb(256, 261, CV_8UC3);
  for (int r = 0; r < rgb.rows; ++r)
    for (int c = 0; c < rgb.cols; ++c)
      rgb.at<cv::Vec3b>(r, c) = cv::Vec3b(r, c % 256, (7 * r + 13 * c) % 256);
  return rgb;
}

TEST(YCbCrPlanes, RgbToPlanesMatchesTheImageTransform) {
  const cv::Mat image = TestImage();
  for (const cv::Mat& rgb : {image, image(cv::Rect(3, 2, 250, 200))}) {  // continuous and a view
    std::vector<cv::Mat> planes;
    RgbToYCbCrPlanes(rgb, planes);
    ASSERT_EQ(planes.size(), 3u);
    std::vector<cv::Mat> expected;
    cv::split(RgbToYCbCr(rgb), expected);
    for (int c = 0; c < 3; ++c) {
      ASSERT_EQ(planes[c].type(), CV_32FC1);
      ASSERT_EQ(planes[c].size(), rgb.size());
      EXPECT_LT(cv::norm(planes[c], expected[c], cv::NORM_INF), 1e-3) << "channel " << c;
    }
  }
}

TEST(YCbCrPlanes, PlanesOfAnImageGiveItsBytesBack) {
  const cv::Mat rgb = TestImage();
  std::vector<cv::Mat> planes;
  RgbToYCbCrPlanes(rgb, planes);
  cv::Mat back(rgb.size(), CV_8UC3, cv::Scalar::all(1));
  YCbCrPlanesToRgb(planes[0], planes[1], planes[2], back);
  EXPECT_EQ(cv::norm(back, rgb, cv::NORM_INF), 0.0);
}

// Out-of-gamut and NaN colours, as the map's expected image can hold: within rounding of
// YCbCrToRgb followed by convertTo (saturated, NaN → 0), into a view whose surroundings stay.
TEST(YCbCrPlanes, PlanesToRgbRoundsAndSaturatesAsConvertTo) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> value(-60.0f, 320.0f);
  const cv::Size size(37, 9);
  cv::Mat y(size, CV_32FC1), cb(size, CV_32FC1), cr(size, CV_32FC1);
  for (cv::Mat* p : {&y, &cb, &cr})
    for (float& v : cv::Mat_<float>(*p)) v = value(rng);
  y.at<float>(4, 20) = std::numeric_limits<float>::quiet_NaN();
  cv::Mat merged, expected;
  cv::merge(std::vector<cv::Mat>{y, cb, cr}, merged);
  YCbCrToRgb(merged).convertTo(expected, CV_8U);
  cv::Mat big(size.height + 2, size.width + 2, CV_8UC3, cv::Scalar::all(77));
  cv::Mat view = big(cv::Rect(1, 1, size.width, size.height));
  YCbCrPlanesToRgb(y, cb, cr, view);
  int saturated = 0;
  for (int r = 0; r < size.height; ++r)
    for (int c = 0; c < size.width; ++c)
      for (int k = 0; k < 3; ++k) {
        const int got = view.at<cv::Vec3b>(r, c)[k], want = expected.at<cv::Vec3b>(r, c)[k];
        EXPECT_LE(std::abs(got - want), 1) << r << "," << c << "," << k;  // ties may round apart
        saturated += want == 0 || want == 255;
      }
  EXPECT_GT(saturated, 50);                                  // the range reaches past both ends
  EXPECT_EQ(view.at<cv::Vec3b>(4, 20), cv::Vec3b(0, 0, 0));  // NaN luma
  EXPECT_EQ(cv::countNonZero(big.row(0).reshape(1) != 77), 0);
  EXPECT_EQ(cv::countNonZero(big.col(0).reshape(1) != 77), 0);
  EXPECT_EQ(cv::countNonZero(big.row(size.height + 1).reshape(1) != 77), 0);
  EXPECT_EQ(cv::countNonZero(big.col(size.width + 1).reshape(1) != 77), 0);
}

TEST(YCbCrPlanes, WrongTypesOrSizesAreRejected) {
  std::vector<cv::Mat> planes;
  EXPECT_THROW(RgbToYCbCrPlanes(cv::Mat(2, 2, CV_32FC3), planes), std::invalid_argument);
  const cv::Mat p(2, 2, CV_32FC1, cv::Scalar(0));
  cv::Mat rgb(2, 2, CV_8UC3);
  EXPECT_NO_THROW(YCbCrPlanesToRgb(p, p, p, rgb));
  cv::Mat wrong_size(2, 3, CV_8UC3), wrong_type(2, 2, CV_32FC3);
  EXPECT_THROW(YCbCrPlanesToRgb(p, p, p, wrong_size), std::invalid_argument);
  EXPECT_THROW(YCbCrPlanesToRgb(p, p, p, wrong_type), std::invalid_argument);
  EXPECT_THROW(YCbCrPlanesToRgb(p, cv::Mat(2, 2, CV_8UC1), p, rgb), std::invalid_argument);
}

}  // namespace
}  // namespace novelty::color
