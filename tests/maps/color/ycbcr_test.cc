#include "maps/color/ycbcr.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace novelty::color {
namespace {

TEST(YCbCr, KnownColours) {
  const cv::Vec3f white = RgbToYCbCr(cv::Vec3f(255, 255, 255));
  EXPECT_NEAR(white[0], 255.0f, 1e-4f);
  EXPECT_NEAR(white[1], 128.0f, 1e-4f);
  EXPECT_NEAR(white[2], 128.0f, 1e-4f);
  // Pure red: Y = 0.299·255, Cr = 127.5 + 128, Cb = -0.168736·255 + 128 (JPEG 2000 ICT table).
  const cv::Vec3f red = RgbToYCbCr(cv::Vec3f(255, 0, 0));
  EXPECT_NEAR(red[0], 76.245f, 1e-3f);
  EXPECT_NEAR(red[1], -0.168736f * 255 + 128, 1e-3f);
  EXPECT_NEAR(red[2], 255.5f, 1e-3f);
  const cv::Vec3f blue = RgbToYCbCr(cv::Vec3f(0, 0, 255));
  EXPECT_NEAR(blue[1], 255.5f, 1e-3f);
  EXPECT_NEAR(blue[2], -0.081312f * 255 + 128, 1e-3f);
}

cv::Matx44d Homogeneous(const cv::Matx34d& m) {
  cv::Matx44d h = cv::Matx44d::eye();
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) h(r, c) = m(r, c);
  return h;
}

TEST(YCbCr, MatricesAreInverse) {
  const cv::Matx44d I = Homogeneous(YCbCrToRgbMatrix()) * Homogeneous(RgbToYCbCrMatrix());
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(I(r, c), r == c ? 1.0 : 0.0, 1e-13);
}

// Every 8-bit RGB triple, as one 4096×4096 image, through the image functions and back.
TEST(YCbCr, RoundTripOfEvery8BitTripleIsWithinHalfALevel) {
  cv::Mat rgb(4096, 4096, CV_8UC3);
  for (int i = 0; i < 4096 * 4096; ++i) {
    rgb.at<cv::Vec3b>(i / 4096, i % 4096) = cv::Vec3b(i >> 16, (i >> 8) & 255, i & 255);
  }
  const cv::Mat back = YCbCrToRgb(RgbToYCbCr(rgb));
  cv::Mat rgb_f;
  rgb.convertTo(rgb_f, CV_32F);
  const double max_err = cv::norm(back, rgb_f, cv::NORM_INF);
  EXPECT_LT(max_err, 0.5);
  EXPECT_LT(max_err, 1e-3) << "float round trip should be exact up to rounding";
  // The scalar path gives the image path's numbers.
  const cv::Vec3f px = RgbToYCbCr(cv::Vec3f(12, 200, 77));
  const cv::Vec3f im = RgbToYCbCr(rgb).at<cv::Vec3f>((12 << 16 | 200 << 8 | 77) / 4096,
                                                     (12 << 16 | 200 << 8 | 77) % 4096);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(px[k], im[k], 1e-4f);
}

TEST(YCbCr, WrongImageTypeIsRejectedWithTheType) {
  EXPECT_THROW(RgbToYCbCr(cv::Mat(2, 2, CV_8UC1)), std::invalid_argument);
  EXPECT_THROW(YCbCrToRgb(cv::Mat(2, 2, CV_8UC3)), std::invalid_argument);
}

}  // namespace
}  // namespace novelty::color
