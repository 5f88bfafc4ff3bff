#include "sensors/dataset/rgbd_sequence.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <opencv2/imgcodecs.hpp>
#include <stdexcept>

namespace novelty::sensors {
namespace {

namespace fs = std::filesystem;

std::string Shared(const std::string& name) {
  const char* shared = std::getenv("NOVELTY_SHARED_DATA");
  const fs::path p = fs::path(shared ? shared : "") / name;
  return shared && fs::exists(p) ? p.string() : "";
}

fs::path Fresh(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / (name + "_" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

// The real sequence: 58 keyframes sharing their timestamps, each with a pose; fr3 from the
// folder's name; 640 × 480 from the first JPEG's header.
TEST(RgbdSequence, ReadsTheTumCabinetKeyframes) {
  const std::string dir = Shared("tum-fr3-cabinet");
  if (dir.empty()) GTEST_SKIP() << "tum-fr3-cabinet/ of the shared data is absent";
  const RgbdSequence s = ReadRgbdSequence(dir);
  EXPECT_EQ(s.layout, "tum");
  ASSERT_EQ(s.frames.size(), 58u);
  EXPECT_EQ(s.unmatched_rgb, 0);
  EXPECT_EQ(s.unposed, 0);
  EXPECT_EQ(s.camera.width, 640);
  EXPECT_EQ(s.camera.height, 480);
  EXPECT_DOUBLE_EQ(s.camera.fx, 535.4);
  EXPECT_DOUBLE_EQ(s.depth_scale, 5000.0);
  EXPECT_DOUBLE_EQ(s.frames[0].time, 1341841278.8427);
  ASSERT_TRUE(s.frames[0].T_world_cam);
  // groundtruth.txt's first line: t = (-2.5508, 0.9872, 1.1019).
  EXPECT_NEAR(
      (s.frames[0].T_world_cam->translation() - Eigen::Vector3d(-2.5508, 0.9872, 1.1019)).norm(),
      0.0, 1e-12);
  EXPECT_TRUE(fs::exists(s.frames[57].depth));
}

TEST(RgbdSequence, ReadsTheIclNuimFolder) {
  const std::string dir = Shared("icl-nuim-5");
  if (dir.empty()) GTEST_SKIP() << "icl-nuim-5/ of the shared data is absent";
  const RgbdSequence s = ReadRgbdSequence(dir);
  EXPECT_EQ(s.layout, "icl-nuim");
  ASSERT_EQ(s.frames.size(), 5u);
  EXPECT_DOUBLE_EQ(s.camera.fy, -480.0);
  EXPECT_NEAR(s.frames[4].time, 4 / 30.0, 1e-12);
}

// A full TUM sequence's lists: depth 10 ms after each colour image (one missing), the motion
// capture 5 ms after; the folder's name gives no camera, so one is named.
TEST(RgbdSequence, AssociatesTumListsByNearestTime) {
  const fs::path dir = Fresh("novelty_tum_lists");
  fs::create_directories(dir / "rgb");
  fs::create_directories(dir / "depth");
  std::ofstream rgb(dir / "rgb.txt"), depth(dir / "depth.txt"), truth(dir / "groundtruth.txt");
  rgb << "# timestamp filename\n";
  for (int k = 0; k < 4; ++k) {
    const double t = 100.0 + k / 30.0;
    const std::string name = std::to_string(k) + ".png";
    cv::imwrite((dir / "rgb" / name).string(), cv::Mat(480, 640, CV_8UC3, cv::Scalar::all(k)));
    rgb << cv::format("%.4f rgb/%s\n", t, name.c_str());
    if (k != 2) depth << cv::format("%.4f depth/%s\n", t + 0.010, name.c_str());
    truth << cv::format("%.4f %d 0 1 0 0 0 1\n", t + 0.005, k);
  }
  rgb.close(), depth.close(), truth.close();
  EXPECT_THROW(ReadRgbdSequence(dir.string()), std::runtime_error) << "no camera named";
  RgbdSequenceOptions o;
  o.camera_name = "fr1";
  const RgbdSequence s = ReadRgbdSequence(dir.string(), o);
  ASSERT_EQ(s.frames.size(), 3u);
  EXPECT_EQ(s.unmatched_rgb, 1);
  EXPECT_EQ(fs::path(s.frames[2].rgb).filename(), "3.png");
  EXPECT_EQ(fs::path(s.frames[2].depth).filename(), "3.png");
  ASSERT_TRUE(s.frames[2].T_world_cam);
  EXPECT_DOUBLE_EQ(s.frames[2].T_world_cam->translation().x(), 3.0);
  o.max_time_difference = 0.001;  // depth 10 ms away: nothing within 1 ms
  EXPECT_THROW(ReadRgbdSequence(dir.string(), o), std::runtime_error);
  fs::remove_all(dir);
}

// 7-Scenes: millimetre depth, 4 × 4 poses, the intrinsics file when there is one.
TEST(RgbdSequence, ReadsTheSevenScenesLayout) {
  const fs::path dir = Fresh("novelty_seven_scenes");
  for (int k = 0; k < 2; ++k) {
    const std::string stem = cv::format("frame-%06d", k);
    cv::imwrite((dir / (stem + ".color.png")).string(),
                cv::Mat(480, 640, CV_8UC3, cv::Scalar::all(9)));
    cv::imwrite((dir / (stem + ".depth.png")).string(),
                cv::Mat(480, 640, CV_16UC1, cv::Scalar(1500)));
    std::ofstream(dir / (stem + ".pose.txt")) << "1 0 0 0.5\n0 1 0 0\n0 0 1 " << k << "\n0 0 0 1\n";
  }
  std::ofstream(dir / "camera-intrinsics.txt") << "580 0 321\n0 581 239\n0 0 1\n";
  const RgbdSequence s = ReadRgbdSequence(dir.string());
  EXPECT_EQ(s.layout, "7scenes");
  ASSERT_EQ(s.frames.size(), 2u);
  EXPECT_DOUBLE_EQ(s.depth_scale, 1000.0);
  EXPECT_EQ(s.invalid_depth, 65535);
  EXPECT_DOUBLE_EQ(s.camera.fy, 581.0);
  EXPECT_DOUBLE_EQ(s.frames[1].T_world_cam->translation().z(), 1.0);
  std::ofstream(dir / "frame-000001.pose.txt") << "2 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n";
  EXPECT_THROW(ReadRgbdSequence(dir.string()), std::runtime_error) << "not a rotation";
  EXPECT_THROW(ReadRgbdSequence((dir / "none").string()), std::runtime_error);
  EXPECT_THROW(NamedCamera("kinect"), std::invalid_argument);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace novelty::sensors
