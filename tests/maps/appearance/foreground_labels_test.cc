#include "maps/appearance/foreground_labels.h"

#include <gtest/gtest.h>

#include <cmath>

namespace novelty::appearance {
namespace {

// A 20×10 frame over a grey-beige background (160, 140, 120): predictive novelty 30 nats (above
// the 16.6 default) in columns 0–15, 0 elsewhere. Columns 0–3 are the background at half its
// linear radiance (a cast shadow), 4–7 a red object, 8–11 the background at 97 % (too slight to
// be a shadow), 12–15 the background at 10 % (darker than a shadow leaves it).
struct Scene {
  cv::Mat background = cv::Mat(10, 20, CV_8UC3, cv::Scalar(160, 140, 120));
  cv::Mat frame = background.clone();
  cv::Mat predictive = cv::Mat(10, 20, CV_32FC1, cv::Scalar(0));
  static cv::Scalar Scaled(double f) {  // the background's linear radiance times f, in 8 bits
    cv::Scalar s;
    const double v[3] = {160, 140, 120};
    for (int c = 0; c < 3; ++c)
      s[c] = std::round(255 * std::pow(f * std::pow(v[c] / 255, 2.2), 1 / 2.2));
    return s;
  }
  Scene() {
    predictive.colRange(0, 16).setTo(30.0f);
    frame.colRange(0, 4).setTo(Scaled(0.5));
    frame.colRange(4, 8).setTo(cv::Scalar(200, 30, 30));
    frame.colRange(8, 12).setTo(Scaled(0.97));
    frame.colRange(12, 16).setTo(Scaled(0.10));
  }
};

TEST(ForegroundLabels, AGreyDarkeningIsShadowAColourChangeIsForeground) {
  const Scene s;
  const cv::Mat l = ForegroundLabels(s.predictive, s.frame, s.background);
  EXPECT_EQ(cv::countNonZero(l.colRange(0, 4) == kShadowLabel), 40);
  EXPECT_EQ(cv::countNonZero(l.colRange(4, 8) == kForegroundLabel), 40);
  EXPECT_EQ(cv::countNonZero(l.colRange(8, 12) == kForegroundLabel), 40);
  EXPECT_EQ(cv::countNonZero(l.colRange(12, 16) == kForegroundLabel), 40);
  EXPECT_EQ(cv::countNonZero(l.colRange(16, 20)), 0);
  ForegroundLabelOptions no_shadow;
  no_shadow.shadow_label = false;
  EXPECT_EQ(cv::countNonZero(ForegroundLabels(s.predictive, s.frame, s.background, no_shadow) ==
                             kForegroundLabel),
            160);
}

TEST(ForegroundLabels, TheThresholdIsInNatsAndNaNIsBackground) {
  Scene s;
  s.predictive.at<float>(0, 5) = std::nanf("");
  ForegroundLabelOptions o;
  o.threshold_nats = 29.9;
  EXPECT_EQ(ForegroundLabels(s.predictive, s.frame, s.background, o).at<uint8_t>(0, 5), 0);
  EXPECT_EQ(ForegroundLabels(s.predictive, s.frame, s.background, o).at<uint8_t>(1, 5), 255);
  o.threshold_nats = 30.0;  // strictly above
  EXPECT_EQ(cv::countNonZero(ForegroundLabels(s.predictive, s.frame, s.background, o)), 0);
}

TEST(ForegroundLabels, BlobsSmallerThanTheMinimumAreDropped) {
  Scene s;
  s.predictive.setTo(0.0f);
  s.frame.setTo(cv::Scalar(200, 30, 30));
  s.predictive(cv::Rect(0, 0, 3, 3)).setTo(30.0f);   // 9 pixels
  s.predictive(cv::Rect(10, 2, 4, 4)).setTo(30.0f);  // 16 pixels
  s.predictive.at<float>(9, 19) = 30.0f;             // 1 pixel
  ForegroundLabelOptions o;
  o.min_blob_pixels = 10;
  const cv::Mat l = ForegroundLabels(s.predictive, s.frame, s.background, o);
  EXPECT_EQ(cv::countNonZero(l), 16);
  EXPECT_EQ(l.at<uint8_t>(3, 11), 255);
  EXPECT_THROW(ForegroundLabels(s.predictive, s.frame, cv::Mat(3, 3, CV_8UC3), o),
               std::invalid_argument);
}

}  // namespace
}  // namespace novelty::appearance
