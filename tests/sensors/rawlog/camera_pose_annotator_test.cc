#include "sensors/rawlog/camera_pose_annotator.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "sensors/rawlog/rawlog_frame_reader.h"
#include "sensors/rawlog/rawlog_output.h"
#include "tests/sensors/some_camera_pose.h"

namespace novelty::sensors {
namespace {

namespace fs = std::filesystem;

// Three RGB-D frames, poses for the first and the third: the copy gives those two frames exactly
// the poses asked for through their own mounting, the second none and its reason kept.
TEST(CameraPoseAnnotator, PosesTheFramesThatGetOneAndKeepsTheRest) {
  const fs::path dir =
      fs::temp_directory_path() / ("novelty_camera_pose_annotator_" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const core::PinholeCamera camera = core::PinholeCamera::FromFov(32, 24, 1.0);
  const cv::Mat rgb(24, 32, CV_8UC3, cv::Scalar(10, 20, 30));
  const cv::Mat depth(24, 32, CV_32F, cv::Scalar(1.5f));
  Eigen::Isometry3d mount = Eigen::Isometry3d::Identity();
  mount.translation() = Eigen::Vector3d(0.1, 0.0, 1.1);
  {
    RawlogOutput out((dir / "in.rawlog").string());
    for (int k = 0; k < 3; ++k)
      out.WriteRgbd(100.0 + 0.1 * k, rgb, depth, camera, mount, cv::format("%06d", k + 1));
    out.Close();
  }
  Eigen::Isometry3d later = SomeCameraPose();
  later.translation() += Eigen::Vector3d(0.2, 0, 0);
  const CameraPoseAt pose_at = [&](double t, std::string* why) -> std::optional<Eigen::Isometry3d> {
    if (std::abs(t - 100.0) < 1e-6) return SomeCameraPose();
    if (std::abs(t - 100.2) < 1e-6) return later;
    *why = "lost";
    return std::nullopt;
  };
  const CameraPoseAnnotation a = AnnotateCameraPoses(
      (dir / "in.rawlog").string(), (dir / "out.rawlog").string(), pose_at, "POSE_TEST");
  EXPECT_EQ(a.cameras, 3);
  EXPECT_EQ(a.posed, 2);
  ASSERT_EQ(a.reasons.size(), 1u);
  EXPECT_EQ(a.reasons[0], "lost");
  ASSERT_EQ(a.poses.size(), 3u);
  EXPECT_FALSE(std::next(a.poses.begin())->second);

  RawlogFrameReader reader((dir / "out.rawlog").string());
  core::Frame f;
  ASSERT_TRUE(reader.Next(f));
  ASSERT_TRUE(f.T_world_cam);
  EXPECT_EQ(f.pose_source, "POSE_TEST");
  EXPECT_LT((f.T_world_cam->matrix() - SomeCameraPose().matrix()).norm(), 1e-9);
  ASSERT_TRUE(reader.Next(f));
  EXPECT_FALSE(f.T_world_cam);
  ASSERT_TRUE(reader.Next(f));
  ASSERT_TRUE(f.T_world_cam);
  EXPECT_LT((f.T_world_cam->matrix() - later.matrix()).norm(), 1e-9);
  EXPECT_EQ(cv::norm(f.rgb, rgb, cv::NORM_INF), 0.0) << "the images are the input's";
  EXPECT_FALSE(reader.Next(f));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace novelty::sensors
