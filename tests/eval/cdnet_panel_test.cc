#include "eval/cdnet_panel.h"

#include <gtest/gtest.h>

#include "eval/cdnet_scores.h"

namespace novelty::eval {
namespace {

// One row of five pixels: motion found, motion missed, a false alarm, a false alarm on shadow and
// an unknown pixel, each in its colour.
TEST(CdnetMaskImage, ColoursHitsMissesAndFalseAlarms) {
  cv::Mat truth = (cv::Mat_<uint8_t>(1, 5) << kCdnetMotion, kCdnetMotion, kCdnetStatic,
                   kCdnetShadow, kCdnetUnknown);
  cv::Mat mask = (cv::Mat_<uint8_t>(1, 5) << 255, 0, 255, 255, 255);
  const cv::Mat m = CdnetMaskImage(mask, truth);
  EXPECT_EQ(m.at<cv::Vec3b>(0, 0), cv::Vec3b(255, 255, 255));
  EXPECT_EQ(m.at<cv::Vec3b>(0, 1)[2], 255);  // blue: missed
  EXPECT_EQ(m.at<cv::Vec3b>(0, 2)[0], 230);  // red: false
  EXPECT_NE(m.at<cv::Vec3b>(0, 3), m.at<cv::Vec3b>(0, 2));
  EXPECT_EQ(m.at<cv::Vec3b>(0, 4), cv::Vec3b(60, 60, 60));
  const cv::Mat roi = (cv::Mat_<uint8_t>(1, 5) << 0, 255, 255, 255, 255);
  EXPECT_EQ(CdnetMaskImage(mask, truth, roi).at<cv::Vec3b>(0, 0), cv::Vec3b(60, 60, 60));
  EXPECT_EQ(CdnetMaskImage(mask).at<cv::Vec3b>(0, 1), cv::Vec3b(0, 0, 0));
  EXPECT_THROW(CdnetMaskImage(cv::Mat(1, 5, CV_8UC3), truth), std::invalid_argument);
}

TEST(CdnetPanel, HoldsCameraTruthAndOneTilePerMethod) {
  const cv::Mat rgb(40, 50, CV_8UC3, cv::Scalar(9, 9, 9)), truth(40, 50, CV_8UC1, cv::Scalar(0));
  const cv::Mat mask(40, 50, CV_8UC1, cv::Scalar(0));
  const cv::Mat with_truth = CdnetPanel(rgb, truth, {}, {mask, mask}, {"a", "b"}, "1");
  const cv::Mat without = CdnetPanel(rgb, {}, {}, {mask, mask}, {"a", "b"}, "1");
  EXPECT_GT(with_truth.cols, 4 * 50);
  EXPECT_GT(without.cols, 3 * 50);
  EXPECT_LT(without.cols, with_truth.cols);
}

}  // namespace
}  // namespace novelty::eval
