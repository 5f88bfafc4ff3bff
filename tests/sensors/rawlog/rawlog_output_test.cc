#include "sensors/rawlog/rawlog_output.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <stdexcept>

#include "sensors/rawlog/rawlog_frame_reader.h"

namespace novelty::sensors {
namespace {

namespace fs = std::filesystem;

void WriteFrames(const std::string& path, int value, int frames, bool fail_after) {
  RawlogOutput out(path);
  const core::PinholeCamera camera = core::PinholeCamera::FromFov(16, 12, 1.0);
  for (int k = 1; k <= frames; ++k)
    out.WriteRgbd(100.0 + k, cv::Mat(12, 16, CV_8UC3, cv::Scalar::all(value)),
                  cv::Mat(12, 16, CV_32F, cv::Scalar(1.0f)), camera, Eigen::Isometry3d::Identity(),
                  cv::format("%06d", k));
  if (fail_after) throw std::runtime_error("a frame cannot be read");
  out.Close();
}

// A run that fails leaves the earlier rawlog and its images as they were, and nothing of its
// own; a run that succeeds replaces both, with no image of the earlier one left over.
TEST(RawlogOutput, AFailedRunLeavesTheEarlierRawlogAndItsImagesWhole) {
  const fs::path dir =
      fs::temp_directory_path() / ("novelty_rawlog_output_" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string rawlog = (dir / "run.rawlog").string();
  WriteFrames(rawlog, 10, 3, false);
  EXPECT_THROW(WriteFrames(rawlog, 200, 2, true), std::runtime_error);
  int entries = 0;
  for (const auto& e : fs::directory_iterator(dir)) ++entries, (void)e;
  EXPECT_EQ(entries, 2) << "run.rawlog and run_Images only";
  RawlogFrameReader reader(rawlog);
  core::Frame f;
  for (int k = 0; k < 3; ++k) {
    ASSERT_TRUE(reader.Next(f));
    EXPECT_EQ(f.rgb.at<cv::Vec3b>(0, 0)[0], 10) << "the earlier run's image, frame " << k + 1;
  }
  WriteFrames(rawlog, 200, 2, false);
  EXPECT_FALSE(fs::exists(dir / "run_Images" / "000003.png")) << "the earlier run's images go";
  RawlogFrameReader again(rawlog);
  ASSERT_TRUE(again.Next(f));
  EXPECT_EQ(f.rgb.at<cv::Vec3b>(0, 0)[0], 200);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace novelty::sensors
