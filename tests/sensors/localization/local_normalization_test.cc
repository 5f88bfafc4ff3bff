#include "sensors/localization/local_normalization.h"

#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgproc.hpp>

#include "tests/sensors/blurred_noise.h"

namespace novelty::sensors {
namespace {

cv::Mat NoiseTexture() {
  return BlurredNoise({80, 60}, CV_32F, 3, 1.0);
}

TEST(LocallyNormalized, IsZeroOnAFlatImage) {
  const cv::Mat flat(40, 50, CV_32F, cv::Scalar(117));
  EXPECT_LT(cv::norm(LocallyNormalized(flat), cv::NORM_INF), 1e-3);
}

TEST(LocallyNormalized, UndoesAGainAndOffsetUpToTheFloor) {
  const cv::Mat texture = NoiseTexture();
  LocalNormalizationOptions o;
  o.floor = 1e-3;  // nearly none: the result is then invariant to I → a·I + b
  const cv::Mat relit = 0.6 * texture + 40;
  const cv::Mat a = LocallyNormalized(texture, o), b = LocallyNormalized(relit, o);
  EXPECT_LT(cv::norm(a, b, cv::NORM_INF), 0.05);
  // With the default floor a darker image reads somewhat lower, never higher.
  const cv::Mat c = LocallyNormalized(texture), d = LocallyNormalized(relit);
  EXPECT_LT(cv::norm(d), cv::norm(c));
  EXPECT_GT(cv::norm(d), 0.5 * cv::norm(c));
}

TEST(LocallyNormalized, MatchesTheClosedFormOnACheckerboard) {
  // A checkerboard: the window's mean and σ in closed form.
  cv::Mat checker(45, 45, CV_32F);
  for (int y = 0; y < checker.rows; ++y)
    for (int x = 0; x < checker.cols; ++x) checker.at<float>(y, x) = (x + y) % 2 ? 180.f : 80.f;
  const cv::Mat n = LocallyNormalized(checker);
  // Window 9×9 around (22, 22): 41 pixels of 80 (the centre's colour), 40 of 180.
  const double mean = (41 * 80.0 + 40 * 180.0) / 81;
  const double sigma = std::sqrt((41 * 80.0 * 80 + 40 * 180.0 * 180) / 81 - mean * mean);
  const double expected = 50.0 * (80 - mean) / (sigma + 10);  // scale 50, floor 10: −41.1
  EXPECT_NEAR(n.at<float>(22, 22), expected, 0.01);
}

TEST(LocallyNormalized, WindowZeroReturnsTheImageAndBadOptionsThrow) {
  const cv::Mat texture = NoiseTexture();
  LocalNormalizationOptions o;
  o.window = 0;
  EXPECT_EQ(cv::norm(LocallyNormalized(texture, o), texture, cv::NORM_INF), 0.0);
  o.window = 8;
  EXPECT_THROW(LocallyNormalized(texture, o), std::invalid_argument);
  o.window = 9;
  o.floor = 0;
  EXPECT_THROW(LocallyNormalized(texture, o), std::invalid_argument);
}

}  // namespace
}  // namespace novelty::sensors
