#include "sim/output/cdnet_writer.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <opencv2/imgcodecs.hpp>

#include "sensors/dataset/cdnet_folder.h"

namespace novelty::sim {
namespace {

namespace fs = std::filesystem;

// A 40×30 frame: object 7 (foreground) in a 10×10 square, its shadow a 6×10 strip to its right
// (background 120 darkened to 90), and a 2-level darkening below it that is not a shadow.
struct Frame {
  cv::Mat ids = cv::Mat(30, 40, CV_32SC1, cv::Scalar(0));
  cv::Mat rgb = cv::Mat(30, 40, CV_8UC3, cv::Scalar(120, 120, 120));
  cv::Mat background = cv::Mat(30, 40, CV_8UC3, cv::Scalar(120, 120, 120));
  Frame() {
    ids(cv::Rect(10, 5, 10, 10)).setTo(7);
    rgb(cv::Rect(10, 5, 10, 10)).setTo(cv::Scalar(200, 30, 30));
    rgb(cv::Rect(22, 5, 6, 10)).setTo(cv::Scalar(90, 90, 90));
    rgb(cv::Rect(10, 20, 10, 5)).setTo(cv::Scalar(118, 118, 118));
  }
};

TEST(CdnetTruth, LabelsMotionItsBorderItsShadowAndNothingElse) {
  const Frame f;
  const cv::Mat t = CdnetTruth(f.ids, {7, 1000}, f.rgb, f.background);
  EXPECT_EQ(cv::countNonZero(t == 255), 100);
  // The unknown ring: 12×12 around the 10×10 square, less the square.
  EXPECT_EQ(cv::countNonZero(t == 170), 144 - 100);
  EXPECT_EQ(t.at<uint8_t>(4, 9), 170);
  EXPECT_EQ(t.at<uint8_t>(10, 20), 170);
  // The shadow strip (x 22…27), all 60 pixels; the 2-level darkening is static.
  EXPECT_EQ(cv::countNonZero(t == 50), 60);
  EXPECT_EQ(t.at<uint8_t>(22, 15), 0);
  EXPECT_EQ(cv::countNonZero(t == 0), 40 * 30 - 100 - 44 - 60);
}

TEST(CdnetTruth, IdsNotInTheForegroundAreStatic) {
  const Frame f;
  const cv::Mat t = CdnetTruth(f.ids, {3}, f.rgb, f.background);
  EXPECT_EQ(cv::countNonZero(t == 255), 0);
  EXPECT_EQ(cv::countNonZero(t == 170), 0);
  EXPECT_THROW(CdnetTruth(f.ids, {7}, f.rgb, cv::Mat(10, 10, CV_8UC3)), std::invalid_argument);
}

TEST(CdnetWriter, WritesAFolderTheCdnetReaderReads) {
  const fs::path dir = fs::temp_directory_path() / "novelty_cdnet_writer_test";
  fs::remove_all(dir);
  const Frame f;
  {
    CdnetWriter w(dir.string(), 2, 3);
    for (int k = 1; k <= 3; ++k)
      w.WriteFrame(k, f.rgb, CdnetTruth(f.ids, {7}, f.rgb, f.background));
  }
  const sensors::CdnetFolder folder = sensors::ReadCdnetFolder(dir.string());
  EXPECT_EQ(folder.numbers, (std::vector<int>{1, 2, 3}));
  EXPECT_EQ(folder.temporal_first, 2);
  EXPECT_EQ(folder.temporal_last, 3);
  EXPECT_FALSE(folder.scored(1));
  ASSERT_EQ(folder.roi.size(), f.rgb.size());
  EXPECT_EQ(cv::countNonZero(folder.roi), 40 * 30);
  const cv::Mat truth = sensors::ReadCdnetTruth(folder.truths[1]);
  EXPECT_EQ(cv::countNonZero(truth == 255), 100);      // PNG: exact
  const cv::Mat input = cv::imread(folder.inputs[0]);  // JPEG: near, in BGR order
  ASSERT_EQ(input.size(), f.rgb.size());
  EXPECT_NEAR(input.at<cv::Vec3b>(10, 15)[2], 200, 12);
  EXPECT_NEAR(input.at<cv::Vec3b>(10, 15)[0], 30, 12);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace novelty::sim
