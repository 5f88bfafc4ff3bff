#include "maps/illumination/spherical_color_change.h"

#include <gtest/gtest.h>

#include <cmath>

namespace novelty::illumination {
namespace {

TEST(SphericalColorChange, IntensityAloneIsNoChange) {
  cv::Mat a(8, 8, CV_32FC3, cv::Scalar(40, 90, 20));
  EXPECT_LT(cv::norm(SphericalColorChange(a * 2.5, a), cv::NORM_INF), 1e-6);
}

TEST(SphericalColorChange, DistanceOfTwoColoursInClosedForm) {
  // Pure red: φ = 0, θ = π/2. Grey: φ = π/4, θ = acos(1/√3). Black: 0.
  const cv::Mat red(1, 1, CV_8UC3, cv::Scalar(200, 0, 0)), grey(1, 1, CV_8UC3, cv::Scalar::all(77));
  const double expected = std::hypot(M_PI / 4, M_PI / 2 - std::acos(1.0 / std::sqrt(3.0)));
  EXPECT_NEAR(SphericalColorChange(red, grey).at<float>(0, 0), expected, 1e-6);
  EXPECT_EQ(SphericalColorChange(cv::Mat::zeros(1, 1, CV_8UC3), grey).at<float>(0, 0), 0.0f);
  EXPECT_THROW(SphericalColorChange(cv::Mat::zeros(1, 1, CV_8UC1), cv::Mat::zeros(1, 1, CV_8UC1)),
               std::invalid_argument);
}

}  // namespace
}  // namespace novelty::illumination
