#include "maps/illumination/missing_texture.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace novelty::illumination {
namespace {

// A log image r = g·x (+ offset): every interior pixel's Sobel/8 gradient is exactly (g, 0), so
// the block means of |∇r̂|² and ∇i·∇r̂ have closed forms.
cv::Mat Ramp(double g, double offset = 0.0, int channels = 1) {
  cv::Mat r(40, 50, CV_32FC(channels));
  for (int y = 0; y < r.rows; ++y)
    for (int x = 0; x < r.cols; ++x)
      for (int c = 0; c < channels; ++c)
        r.ptr<float>(y)[x * channels + c] = float(g * x + offset + 0.1 * c);
  return r;
}

float Interior(const cv::Mat& m) {
  return m.at<float>(20, 25);
}

TEST(MissingTexture, AnObjectThatHidesTheTextureMissesAllOfItsEnergy) {
  const double g = 0.2;
  const cv::Mat r = Ramp(g);
  const cv::Mat uniform(r.size(), CV_32F, cv::Scalar(4.0f));       // no gradient at all
  EXPECT_NEAR(Interior(MissingTexture(uniform, r)), g * g, 1e-6);  // |∇r̂|² = g²
  // A quarter of the contrast left: (g² - g·g/4) = 3g²/4.
  EXPECT_NEAR(Interior(MissingTexture(Ramp(g / 4), r)), 0.75 * g * g, 1e-6);
}

TEST(MissingTexture, LightingThatAddsOrStrengthensTextureHidesNothing) {
  const cv::Mat r = Ramp(0.2);
  // A uniform light (a constant in the log domain), a shadow's interior, hides nothing.
  EXPECT_NEAR(Interior(MissingTexture(Ramp(0.2, -1.5), r)), 0.0, 1e-6);
  // Shading across the texture (∇l ⊥ ∇r̂) hides nothing.
  cv::Mat shaded = r.clone();
  for (int y = 0; y < r.rows; ++y) shaded.row(y) += 0.05 * y;
  EXPECT_NEAR(Interior(MissingTexture(shaded, r)), 0.0, 1e-6);
  // Stronger contrast (∇i·∇r̂ > |∇r̂|²) is not negative missing texture.
  EXPECT_NEAR(Interior(MissingTexture(Ramp(0.4), r)), 0.0, 1e-6);
}

TEST(MissingTexture, ChannelsAddUp) {
  const cv::Mat r = Ramp(0.2, 0.0, 3);
  const cv::Mat uniform(r.size(), CV_32FC3, cv::Scalar::all(4.0));
  EXPECT_NEAR(Interior(MissingTexture(uniform, r)), 3 * 0.04, 1e-6);
}

TEST(MissingTexture, NoGradientThatReachesAnUncoveredPixelCounts) {
  const cv::Mat r = Ramp(0.2);
  const cv::Mat uniform(r.size(), CV_32F, cv::Scalar(4.0f));
  cv::Mat covered(r.size(), CV_8U, cv::Scalar(255));
  covered.colRange(0, 25).setTo(0);
  MissingTextureOptions one;
  one.block = 1;
  const cv::Mat m = MissingTexture(uniform, r, covered, one);
  EXPECT_EQ(m.at<float>(20, 25), 0.0f);  // its 3×3 support holds column 24
  EXPECT_NEAR(m.at<float>(20, 26), 0.04, 1e-6);
  // A 7-pixel block at column 28 spans columns 25 … 31; column 25 reaches 24: 6 of 7 count.
  const cv::Mat b = MissingTexture(uniform, r, covered);
  EXPECT_NEAR(b.at<float>(20, 28), 0.04 * 6.0 / 7.0, 1e-6);
}

TEST(MissingTexture, AFullyCoveredMaskIsNoMaskAlsoAtTheImageBorder) {
  cv::Mat r(30, 40, CV_32FC3), i(30, 40, CV_32FC3);
  cv::RNG(7).fill(r, cv::RNG::UNIFORM, 0.0, 5.0);
  cv::RNG(8).fill(i, cv::RNG::UNIFORM, 0.0, 5.0);
  const cv::Mat all(r.size(), CV_8U, cv::Scalar(255));
  EXPECT_EQ(cv::norm(TextureChange(i, r, all), TextureChange(i, r), cv::NORM_INF), 0.0);
}

TEST(MissingTexture, BadInputIsAnError) {
  const cv::Mat r = Ramp(0.2);
  EXPECT_THROW(MissingTexture(Ramp(0.2, 0.0, 3), r), std::invalid_argument);
  EXPECT_THROW(MissingTexture(r(cv::Rect(0, 0, 10, 10)), r), std::invalid_argument);
  cv::Mat bytes;
  r.convertTo(bytes, CV_8U);
  EXPECT_THROW(MissingTexture(bytes, bytes), std::invalid_argument);
  EXPECT_THROW(MissingTexture(r, r, cv::Mat(3, 3, CV_8U)), std::invalid_argument);
  MissingTextureOptions even;
  even.block = 4;
  EXPECT_THROW(MissingTexture(r, r, {}, even), std::invalid_argument);
}

}  // namespace
}  // namespace novelty::illumination
