#include "eval/novelty_panel.h"

#include <gtest/gtest.h>

#include <limits>

#include "core/false_color.h"

namespace novelty::eval {
namespace {

TEST(NoveltyPanel, FiveCaptionedTilesWithTheCameraImageFirst) {
  const int w = 40, h = 30;
  cv::Mat rgb(h, w, CV_8UC3, cv::Scalar(10, 200, 30));
  appearance::AppearanceProducts p;
  p.expected_rgb = cv::Mat(h, w, CV_8UC3, cv::Scalar(1, 2, 3));
  p.surprise = cv::Mat(h, w, CV_32FC1, cv::Scalar(5));
  p.uncertainty = cv::Mat(h, w, CV_32FC1, cv::Scalar(std::numeric_limits<float>::quiet_NaN()));
  appearance::DifferencingProducts d;
  d.difference = cv::Mat(h, w, CV_32FC1, cv::Scalar(300));  // beyond the scale: brightest
  const cv::Mat panel = NoveltyPanel(rgb, p, &d, "000042");
  EXPECT_EQ(panel.type(), CV_8UC3);
  EXPECT_EQ(panel.cols, 5 * w + 4 * 4);
  EXPECT_GT(panel.rows, h);  // the caption strip
  // The camera tile is the image itself, and the expected image the second tile.
  const int strip = panel.rows - h;
  EXPECT_EQ(cv::norm(panel(cv::Rect(0, strip, w, h)), rgb, cv::NORM_INF), 0.0);
  EXPECT_EQ(cv::norm(panel(cv::Rect(w + 4, strip, w, h)), p.expected_rgb, cv::NORM_INF), 0.0);
  // Differencing clamped to its scale draws as the top of the colour map, as FalseColor does.
  const cv::Mat top = core::FalseColor(cv::Mat(1, 1, CV_32FC1, cv::Scalar(150)), 150.0);
  EXPECT_EQ(panel.at<cv::Vec3b>(strip + 5, 4 * (w + 4) + 5), top.at<cv::Vec3b>(0, 0));
  // Without a differencing map: the first four tiles alone, the same.
  const cv::Mat four = NoveltyPanel(rgb, p, nullptr, "000042");
  EXPECT_EQ(four.cols, 4 * w + 3 * 4);
  ASSERT_EQ(four.rows, panel.rows);
  const cv::Rect tiles(0, strip, four.cols, h);
  EXPECT_EQ(cv::norm(four(tiles), panel(tiles), cv::NORM_INF), 0.0);
}

}  // namespace
}  // namespace novelty::eval
