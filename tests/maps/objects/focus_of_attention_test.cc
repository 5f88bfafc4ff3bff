#include "maps/objects/focus_of_attention.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>

namespace novelty::objects {
namespace {

// Low noise everywhere, a surprising rectangle (an object), a single surprising speck elsewhere.
cv::Mat Scene(cv::Rect object, float level) {
  cv::Mat s(120, 160, CV_32F);
  cv::RNG(4).fill(s, cv::RNG::UNIFORM, 0.0f, 0.5f);
  s(object).setTo(level);
  s.at<float>(10, 150) = 100.0f;  // sensor noise, one pixel: the opening removes it
  return s;
}

TEST(FocusOfAttention, TheBoxIsTheSurprisingObjectsAndNotTheSpeck) {
  const cv::Rect object(40, 30, 25, 18);
  const FocusOfAttention f = FindFocusOfAttention(Scene(object, 20.0f));
  EXPECT_EQ(f.box, object);
  EXPECT_TRUE(object.contains(f.seed));
  EXPECT_EQ(cv::countNonZero(f.region), object.area());
  // θ_S = μ_S + 2σ_S of the opened map, computed here directly: the object's share a = 450/19200
  // at 20 and the rest at about 0.25 (uniform 0…0.5, closed then opened: close to its mean).
  cv::Scalar mean, stddev;
  cv::meanStdDev(f.surprise, mean, stddev);
  EXPECT_NEAR(f.threshold, mean[0] + 2 * stddev[0], 1e-9);
  const double a = double(object.area()) / (120 * 160);
  EXPECT_NEAR(f.threshold, 20 * a + 0.25 * (1 - a) + 2 * (20 - 0.25) * std::sqrt(a * (1 - a)), 0.2);
}

TEST(FocusOfAttention, UncoveredPixelsAreLeftOutAndNeverFilled) {
  const cv::Rect object(40, 30, 25, 18);
  cv::Mat s = Scene(object, 20.0f);
  s(cv::Rect(0, 0, 160, 60)).setTo(std::numeric_limits<float>::quiet_NaN());  // top half
  const FocusOfAttention f = FindFocusOfAttention(s);  // the object lies in the NaN half
  EXPECT_GE(f.seed.y, 60);
  EXPECT_GE(f.box.y, 60);
  const cv::Rect lower(40, 70, 25, 18);
  s(lower).setTo(30.0f);
  const FocusOfAttention g = FindFocusOfAttention(s);
  EXPECT_EQ(g.box, lower);
  EXPECT_EQ(cv::countNonZero(g.region(cv::Rect(0, 0, 160, 60))), 0);
}

TEST(FocusOfAttention, TheShareOfASurprisingWindow) {
  const cv::Rect object(40, 30, 40, 40);
  const FocusOfAttention f = FindFocusOfAttention(Scene(object, 20.0f));
  // Windows inside, astride the left border (half), outside; turned by 45° inside.
  EXPECT_DOUBLE_EQ(SurprisingShare(f, {60, 50}, 20, 0), 1.0);
  EXPECT_DOUBLE_EQ(SurprisingShare(f, {39.5f, 50}, 20, 0), 0.5);  // [29.5, 49.5) across x = 39.5
  EXPECT_DOUBLE_EQ(SurprisingShare(f, {120, 100}, 20, 0), 0.0);
  EXPECT_DOUBLE_EQ(SurprisingShare(f, {60, 50}, 20, float(M_PI / 4)), 1.0);
  EXPECT_DOUBLE_EQ(SurprisingShare(f, {158, 118}, 20, 0), 0.0) << "outside the image: not surprising";
}

TEST(FocusOfAttention, BadInputIsRejected) {
  EXPECT_THROW(FindFocusOfAttention(cv::Mat(10, 10, CV_64F)), std::invalid_argument);
  FocusOfAttentionOptions o;
  o.xi = -1;
  EXPECT_THROW(FindFocusOfAttention(cv::Mat(10, 10, CV_32F, cv::Scalar(1)), o),
               std::invalid_argument);
  const FocusOfAttention empty = FindFocusOfAttention(
      cv::Mat(10, 10, CV_32F, cv::Scalar(std::numeric_limits<float>::quiet_NaN())));
  EXPECT_TRUE(empty.box.empty());
  EXPECT_EQ(empty.seed, cv::Point(-1, -1));
}

// Marked pixels count as surprising in ρ_S, the rest as before, and the focus given is untouched.
TEST(FocusOfAttention, MarkedPixelsCountAsSurprising) {
  cv::Mat surprise(120, 160, CV_32FC1, cv::Scalar(1.0f));
  surprise(cv::Rect(60, 40, 40, 40)).setTo(20.0f);
  const FocusOfAttention focus = FindFocusOfAttention(surprise);
  // A 40 × 40 window centred at (40, 60), left of the surprising square: nothing on surprise.
  EXPECT_DOUBLE_EQ(SurprisingShare(focus, {40.0f, 60.0f}, 40.0f, 0.0f), 0.0);
  cv::Mat mask = cv::Mat::zeros(surprise.size(), CV_8UC1);
  mask(cv::Rect(20, 40, 20, 40)).setTo(255);  // the window's left half
  const FocusOfAttention marked = MarkSurprising(focus, mask);
  EXPECT_NEAR(SurprisingShare(marked, {40.0f, 60.0f}, 40.0f, 0.0f), 0.5, 1e-9);
  EXPECT_DOUBLE_EQ(SurprisingShare(focus, {40.0f, 60.0f}, 40.0f, 0.0f), 0.0);
  EXPECT_DOUBLE_EQ(SurprisingShare(marked, {80.0f, 60.0f}, 30.0f, 0.0f),
                   SurprisingShare(focus, {80.0f, 60.0f}, 30.0f, 0.0f));
  EXPECT_EQ(marked.box, focus.box);
  EXPECT_EQ(marked.threshold, focus.threshold);
  EXPECT_THROW(MarkSurprising(focus, cv::Mat::zeros(10, 10, CV_8UC1)), std::invalid_argument);
}

// The region grows over the mask's pixels that touch it (8-connected, a diagonal included), not
// over those apart from it; surprise, θ_S and seed stay.
TEST(FocusOfAttention, TheFocusGrowsOverTheTouchingPartOfTheMask) {
  cv::Mat surprise(120, 160, CV_32FC1, cv::Scalar(1.0f));
  surprise(cv::Rect(60, 40, 20, 20)).setTo(20.0f);  // a patch of an object: x 60–79, y 40–59
  const FocusOfAttention focus = FindFocusOfAttention(surprise);
  ASSERT_EQ(focus.box, cv::Rect(60, 40, 20, 20));
  const cv::Mat surprise_before = focus.surprise.clone();  // shared with the grown focus
  cv::Mat mask = cv::Mat::zeros(surprise.size(), CV_8UC1);
  mask(cv::Rect(70, 50, 30, 30)).setTo(255);  // the whole object, overlapping: x 70–99, y 50–79
  mask(cv::Rect(100, 80, 5, 5)).setTo(255);   // touching its corner diagonally: x, y to 104, 84
  mask(cv::Rect(10, 10, 10, 10)).setTo(255);  // nearer too, but apart
  const FocusOfAttention grown = GrowFocus(focus, mask);
  EXPECT_EQ(grown.box, cv::Rect(60, 40, 45, 45));
  EXPECT_EQ(cv::countNonZero(grown.region), 400 + 900 - 100 + 25);
  EXPECT_EQ(cv::countNonZero(grown.region(cv::Rect(10, 10, 10, 10))), 0);
  EXPECT_EQ(grown.seed, focus.seed);
  EXPECT_EQ(grown.threshold, focus.threshold);
  EXPECT_EQ(cv::norm(grown.surprise, surprise_before, cv::NORM_INF), 0.0);
  EXPECT_EQ(GrowFocus(focus, cv::Mat::zeros(surprise.size(), CV_8UC1)).box, focus.box);
  EXPECT_THROW(GrowFocus(focus, cv::Mat::zeros(10, 10, CV_8UC1)), std::invalid_argument);
  // Without a seed (nothing covered) there is nothing to grow from.
  const FocusOfAttention none = FindFocusOfAttention(
      cv::Mat(120, 160, CV_32F, cv::Scalar(std::numeric_limits<float>::quiet_NaN())));
  EXPECT_TRUE(GrowFocus(none, mask).box.empty());
}

// θ_S is a double, the surprise float: on random maps (θ_S rounding either way) every marked
// pixel passes SurprisingShare's test, so a window inside the mask has ρ_S = 1.
TEST(FocusOfAttention, MarkedPixelsReachTheThresholdWhateverItsRounding) {
  cv::RNG rng(5);
  cv::Mat mask = cv::Mat::zeros(60, 80, CV_8UC1);
  mask(cv::Rect(10, 10, 30, 30)).setTo(255);
  int rounded_down = 0;
  for (int i = 0; i < 50; ++i) {
    cv::Mat surprise(60, 80, CV_32FC1);
    rng.fill(surprise, cv::RNG::UNIFORM, 0.0f, 10.0f);
    const FocusOfAttention focus = FindFocusOfAttention(surprise);
    rounded_down += double(float(focus.threshold)) < focus.threshold;
    const FocusOfAttention marked = MarkSurprising(focus, mask);
    for (int y = 10; y < 40; ++y)
      for (int x = 10; x < 40; ++x)
        ASSERT_GE(double(marked.surprise.at<float>(y, x)), focus.threshold) << i;
    EXPECT_DOUBLE_EQ(SurprisingShare(marked, {25.0f, 25.0f}, 20.0f, 0.0f), 1.0) << i;
  }
  EXPECT_GT(rounded_down, 0) << "no map whose θ_S rounds down: the case is not tested";
}

}  // namespace
}  // namespace novelty::objects
