#include "sensors/dataset/fixed_camera_frames.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/videoio.hpp>

namespace novelty::sensors {
namespace {

namespace fs = std::filesystem;

// Five 32×24 frames, frame k of grey level 40·k, as a plain folder, a CDnet folder and an MJPG
// video (OpenCV's own encoder, read back through FFmpeg).
class FixedCameraFramesTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("fixed_camera_frames_" + std::to_string(getpid()));
    fs::remove_all(dir_);
    for (const char* d : {"plain", "cdnet/input", "cdnet/groundtruth"})
      fs::create_directories(dir_ / d);
    cv::VideoWriter video((dir_ / "clip.avi").string(), cv::VideoWriter::fourcc('M', 'J', 'P', 'G'),
                          10, {32, 24});
    ASSERT_TRUE(video.isOpened());
    for (int k = 1; k <= 5; ++k) {
      const cv::Mat frame(24, 32, CV_8UC3, cv::Scalar(40 * k, 40 * k, 40 * k));
      char name[32];
      std::snprintf(name, sizeof name, "frame_%02d.png", k);
      ASSERT_TRUE(cv::imwrite((dir_ / "plain" / name).string(), frame));
      std::snprintf(name, sizeof name, "in%06d.jpg", k);
      ASSERT_TRUE(cv::imwrite((dir_ / "cdnet/input" / name).string(), frame));
      video.write(frame);
    }
    video.release();
    ASSERT_TRUE(cv::imwrite((dir_ / "cdnet/groundtruth/gt000004.png").string(),
                            cv::Mat(24, 32, CV_8UC1, cv::Scalar(0))));
    std::ofstream(dir_ / "cdnet/temporalROI.txt") << "3 5\n";
  }
  void TearDown() override { fs::remove_all(dir_); }
  // Every frame's number and grey level.
  static std::vector<std::pair<int, int>> Read(FixedCameraFrames& f) {
    std::vector<std::pair<int, int>> out;
    for (FixedCameraFrame frame; f.Next(frame);)
      out.push_back({frame.number, frame.rgb.at<cv::Vec3b>(12, 16)[0]});
    return out;
  }
  fs::path dir_;
};

TEST_F(FixedCameraFramesTest, APlainFolderIsNumberedInNameOrder) {
  FixedCameraFrames f((dir_ / "plain").string());
  EXPECT_EQ(f.kind(), "image folder");
  EXPECT_EQ(f.size(), 5);
  EXPECT_TRUE(f.scored(1));
  EXPECT_EQ(Read(f),
            (std::vector<std::pair<int, int>>{{1, 40}, {2, 80}, {3, 120}, {4, 160}, {5, 200}}));
}

TEST_F(FixedCameraFramesTest, ACdnetFolderBringsItsTruthAndTemporalRoi) {
  FixedCameraFrames f((dir_ / "cdnet").string());
  EXPECT_EQ(f.kind(), "CDnet folder");
  EXPECT_FALSE(f.scored(2));
  EXPECT_TRUE(f.scored(4));
  FixedCameraFrame frame;
  int with_truth = 0;
  while (f.Next(frame)) with_truth += !frame.truth.empty();
  EXPECT_EQ(with_truth, 1);
}

TEST_F(FixedCameraFramesTest, AVideoIsReadFrameByFrameInRgb) {
  FixedCameraFrames f((dir_ / "clip.avi").string());
  EXPECT_EQ(f.kind(), "video");
  EXPECT_EQ(f.size(), 5);
  const auto frames = Read(f);
  ASSERT_EQ(frames.size(), 5u);
  for (int k = 0; k < 5; ++k) {
    EXPECT_EQ(frames[std::size_t(k)].first, k + 1);
    EXPECT_NEAR(frames[std::size_t(k)].second, 40 * (k + 1), 4);  // MJPG is lossy
  }
}

TEST_F(FixedCameraFramesTest, WhatIsNeitherIsAnErrorNamingIt) {
  std::ofstream(dir_ / "notes.txt") << "not a video\n";
  fs::create_directories(dir_ / "empty");
  for (const fs::path& bad : {dir_ / "notes.txt", dir_ / "none", dir_ / "empty"}) {
    try {
      FixedCameraFrames f(bad.string());
      for (FixedCameraFrame frame; f.Next(frame);) {
      }
      ADD_FAILURE() << bad << " accepted";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find(bad.string()), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(FixedCameraFrames((dir_ / "clip.avi").string(), 100), std::runtime_error);
  cv::imwrite((dir_ / "plain/frame_06.png").string(), cv::Mat(10, 10, CV_8UC3));
  FixedCameraFrames f((dir_ / "plain").string());
  EXPECT_THROW(Read(f), std::runtime_error);
}

}  // namespace
}  // namespace novelty::sensors
