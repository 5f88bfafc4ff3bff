#include "maps/illumination/gradient_correlation.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

namespace novelty::illumination {
namespace {

cv::Mat Texture() {
  cv::Mat t(96, 128, CV_32FC3);
  cv::RNG(9).fill(t, cv::RNG::UNIFORM, 20, 200);
  cv::GaussianBlur(t, t, {0, 0}, 1.5);
  return t;
}

TEST(GradientCorrelation, IgnoresGainAndOffsetAndFindsANewObject) {
  const cv::Mat reference = Texture();
  // I2 = α I1 + β with α = 0.6: with E the block's energy and t = E/c, the regularised
  // ρ = (0.6 t + 1) / sqrt((t + 1)(0.36 t + 1)) ≥ 0.967 for every t, so 1 - ρ ≤ 0.033.
  const cv::Mat brighter = reference * 0.6 + cv::Scalar::all(30);
  EXPECT_LT(cv::norm(GradientCorrelationChange(brighter, reference), cv::NORM_INF), 0.034);
  // A flat new object over the texture: its blocks lose all correlation; away from it nothing.
  cv::Mat observation = reference.clone();
  observation(cv::Rect(40, 30, 32, 32)).setTo(cv::Scalar::all(120));
  // At full resolution every block inside it compares plain with texture (E ≫ c): ρ ≈ 0.
  GradientCorrelationOptions one_layer;
  one_layer.layers = 1;
  const cv::Mat change = GradientCorrelationChange(observation, reference, one_layer);
  EXPECT_GT(cv::mean(change(cv::Rect(46, 36, 20, 20)))[0], 0.8);
  EXPECT_LT(cv::mean(change(cv::Rect(0, 0, 20, 96)))[0], 0.05);
  // Coarser layers mix its inside with its border and the texture around: less, still high.
  const cv::Mat layered = GradientCorrelationChange(observation, reference);
  EXPECT_GT(cv::mean(layered(cv::Rect(46, 36, 20, 20)))[0], 0.5);
  EXPECT_LT(cv::mean(layered(cv::Rect(0, 0, 20, 96)))[0], 0.05);
}

TEST(GradientCorrelation, AFlippedEdgeIsNoChangeButAShadowBorderIs) {
  // A step edge that shading makes dark-to-bright instead of bright-to-dark: |.| keeps ρ = 1.
  cv::Mat a(40, 40, CV_32F, cv::Scalar(50)), b(40, 40, CV_32F, cv::Scalar(150));
  a.colRange(20, 40).setTo(150);
  b.colRange(20, 40).setTo(50);
  GradientCorrelationOptions one_layer;
  one_layer.layers = 1;
  EXPECT_LT(cv::norm(GradientCorrelationChange(a, b, one_layer), cv::NORM_INF), 1e-5);
  // A shadow border where the reference is flat: ρ = sqrt(c / (E + c)) ≈ 0 along it (the
  // weakness 6.5 names); flat in both: ρ = 1.
  cv::Mat flat(40, 40, CV_32F, cv::Scalar(100));
  const cv::Mat change = GradientCorrelationChange(a, flat, one_layer);
  EXPECT_GT(change.at<float>(20, 20), 0.9f);
  EXPECT_FLOAT_EQ(change.at<float>(20, 5), 0.0f);
}

TEST(GradientCorrelation, RejectsMismatchedInputsAndBadOptions) {
  const cv::Mat a = cv::Mat::zeros(20, 20, CV_32F);
  EXPECT_THROW(GradientCorrelationChange(a, cv::Mat::zeros(20, 21, CV_32F)), std::invalid_argument);
  GradientCorrelationOptions even;
  even.block = 4;
  EXPECT_THROW(GradientCorrelationChange(a, a, even), std::invalid_argument);
}

}  // namespace
}  // namespace novelty::illumination
