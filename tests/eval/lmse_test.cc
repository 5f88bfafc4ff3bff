#include "eval/lmse.h"

#include <gtest/gtest.h>

#include <opencv2/core.hpp>

namespace novelty::eval {
namespace {

cv::Mat Random(cv::Size size, int seed) {
  cv::RNG rng(seed);
  cv::Mat m(size, CV_32F);
  rng.fill(m, cv::RNG::UNIFORM, 0.1, 1.0);
  return m;
}

const cv::Mat kAll(40, 60, CV_8U, cv::Scalar(255));

TEST(Lmse, IsZeroForAScaledTruthAndOneForAZeroEstimate) {
  const cv::Mat t = Random(kAll.size(), 1);
  EXPECT_NEAR(LocalMse(t, 3.7 * t, kAll), 0.0, 1e-12);
  EXPECT_NEAR(LocalMse(t, cv::Mat::zeros(t.size(), CV_32F), kAll), 1.0, 1e-12);
}

TEST(Lmse, HandComputedWindow) {
  // One 2 × 2 window: truth 1 2 / 3 4, estimate constant → a = 10/4, Σ(t - a)² = 5, Σt² = 30.
  const cv::Mat t = (cv::Mat_<float>(2, 2) << 1, 2, 3, 4);
  const cv::Mat mask(2, 2, CV_8U, cv::Scalar(255));
  EXPECT_NEAR(LocalMse(t, cv::Mat::ones(2, 2, CV_32F), mask, 2), 5.0 / 30.0, 1e-12);
  // Masking the 4 out: a = 6/3 = 2, Σ(t - 2)² = 2, Σt² = 14.
  cv::Mat partial = mask.clone();
  partial.at<uchar>(1, 1) = 0;
  EXPECT_NEAR(LocalMse(t, cv::Mat::ones(2, 2, CV_32F), partial, 2), 2.0 / 14.0, 1e-12);
}

TEST(Lmse, EachWindowHasItsOwnScale) {
  // With 1 × 1 windows every pixel is scaled alone: any positive factor per pixel costs nothing;
  // one window over the whole image allows one factor only.
  const cv::Mat t = Random(kAll.size(), 2);
  const cv::Mat scaled = t.mul(Random(kAll.size(), 3));
  EXPECT_NEAR(LocalMse(t, scaled, kAll, 1), 0.0, 1e-12);
  EXPECT_GT(LocalMse(t, scaled, kAll, 40), 0.05);
}

TEST(Lmse, ScoreAveragesShadingAndReflectanceAndColourChannels) {
  const cv::Mat s = Random(kAll.size(), 4), r = Random(kAll.size(), 5);
  const cv::Mat zero = cv::Mat::zeros(kAll.size(), CV_32F);
  // Reflectance in colour: one channel right, two zero → (0 + 1 + 1) / 3.
  cv::Mat colour;
  cv::merge(std::vector<cv::Mat>{2.0 * r, zero, zero}, colour);
  const IntrinsicScore score = ScoreIntrinsic(s, r, s, colour, kAll);
  EXPECT_NEAR(score.shading, 0.0, 1e-12);
  EXPECT_NEAR(score.reflectance, 2.0 / 3.0, 1e-12);
  EXPECT_NEAR(score.lmse, 1.0 / 3.0, 1e-12);
  EXPECT_THROW(LocalMse(s, r, cv::Mat(kAll.size(), CV_32F)), std::invalid_argument);
  EXPECT_THROW(LocalMse(s, r.colRange(0, 10), kAll), std::invalid_argument);
}

}  // namespace
}  // namespace novelty::eval
