#include "sensors/rawlog/camera_pose_observation.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "sensors/rawlog/rawlog_frame_reader.h"
#include "sensors/rawlog/rawlog_output.h"
#include "tests/sensors/some_camera_pose.h"

namespace novelty::sensors {
namespace {

namespace fs = std::filesystem;

// A pose observation before an RGB-D frame with its timestamp gives that frame its camera pose
// through the frame's own mounting; a frame without one gets none.
TEST(CameraPoseObservation, FrameReaderRecoversTheCameraPose) {
  const fs::path dir = fs::temp_directory_path() / "novelty_camera_pose_observation";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const core::PinholeCamera camera = core::PinholeCamera::FromFov(32, 24, 1.0);
  const cv::Mat rgb(24, 32, CV_8UC3, cv::Scalar(10, 20, 30));
  const cv::Mat depth(24, 32, CV_32F, cv::Scalar(1.5f));
  Eigen::Isometry3d mount = Eigen::Isometry3d::Identity();
  mount.linear() = Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitY()).toRotationMatrix();
  mount.translation() = Eigen::Vector3d(0.1, 0.0, 1.1);
  {
    RawlogOutput out((dir / "poses.rawlog").string());
    out.Write(
        MakeCameraPoseObservation(100.0, SomeCameraPose(), mount, "POSE_TRACKER", 0.001, 0.003));
    out.WriteRgbd(100.0, rgb, depth, camera, mount, "000001");
    out.WriteRgbd(100.2, rgb, depth, camera, mount, "000002");  // no pose for this one
    out.Close();
  }
  RawlogFrameReader reader((dir / "poses.rawlog").string());
  core::Frame f;
  ASSERT_TRUE(reader.Next(f));
  ASSERT_TRUE(f.T_world_cam);
  EXPECT_EQ(f.pose_source, "POSE_TRACKER");
  EXPECT_LT((f.T_world_cam->matrix() - SomeCameraPose().matrix()).norm(), 1e-9);
  ASSERT_TRUE(reader.Next(f));
  EXPECT_FALSE(f.T_world_cam);
}

}  // namespace
}  // namespace novelty::sensors
