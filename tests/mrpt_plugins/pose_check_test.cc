#include "mrpt_plugins/pose_check.h"

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>

#include <cmath>

namespace novelty::mrpt_plugins {
namespace {

// A robot at (x, y, yaw) carrying a camera 1 m high, pitched down by `pitch` (optical frame:
// +Z forward, +Y down), as T_world_cam = robot ⊕ camera-on-robot.
Eigen::Isometry3d RobotFromCamera(double pitch) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  Eigen::Matrix3d level;
  level.col(0) << 0, -1, 0;  // camera x: robot's right
  level.col(1) << 0, 0, -1;  // camera y: down
  level.col(2) << 1, 0, 0;   // camera z: forward
  t.linear() = Eigen::AngleAxisd(pitch, Eigen::Vector3d::UnitY()).toRotationMatrix() * level;
  t.translation() << 0.2, 0.0, 1.0;
  return t;
}
Eigen::Isometry3d Robot(double x, double y, double yaw) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  t.translation() << x, y, 0.0;
  return t;
}

// A robot driving an arc at 0.5 m/s and 30 deg/s, 10 frames a second: nothing to report.
TEST(PoseCheck, ARobotsTrajectoryIsPlausible) {
  PoseCheck check;
  for (int k = 0; k < 100; ++k) {
    const double t = 0.1 * k, w = 30.0 * M_PI / 180.0, r = 0.5 / w, yaw = w * t;
    const Eigen::Isometry3d camera = Robot(r * std::sin(yaw), r * (1.0 - std::cos(yaw)), yaw) *
                                     RobotFromCamera(25.0 * M_PI / 180.0);
    EXPECT_EQ(check.Check(camera, t), "") << "frame " << k;
  }
  EXPECT_EQ(check.warnings(), 0);
}

// The camera's own pose passed as the robot's: the camera-on-robot rotation applied twice rolls
// the image by 90 degrees (its up is horizontal).
TEST(PoseCheck, TheCameraPosePassedAsTheRobotPoseIsReported) {
  PoseCheck check;
  const Eigen::Isometry3d true_camera = Robot(1, 2, 0.3) * RobotFromCamera(0.0);
  const std::string problem = check.Check(true_camera * RobotFromCamera(0.0), 0.0);
  EXPECT_NE(problem.find("camera tilted 90 deg from upright (limit 60 deg)"), std::string::npos)
      << problem;
  EXPECT_EQ(check.warnings(), 1);
}

// Limits, each on both sides: tilt 55 / 65 deg; height; 0.19 / 0.21 m in 0.1 s at 2 m/s; a
// turn of 17 / 19 deg in 0.1 s at 180 deg/s; no timestamps count as 0.1 s.
TEST(PoseCheck, EachLimitOnBothSides) {
  const double deg = M_PI / 180.0;
  EXPECT_EQ(PoseCheck().Check(RobotFromCamera(55 * deg), 0.0), "");
  EXPECT_NE(PoseCheck().Check(RobotFromCamera(65 * deg), 0.0), "");
  Eigen::Isometry3d low = RobotFromCamera(0.0);
  low.translation().z() = -0.1;
  EXPECT_NE(PoseCheck().Check(low, 0.0).find("below the floor"), std::string::npos);
  for (const auto& [step, turn, time, expect] : {std::tuple{0.19, 0.0, 0.1, false},
                                                 {0.21, 0.0, 0.1, true},
                                                 {0.0, 17.0, 0.1, false},
                                                 {0.0, 19.0, 0.1, true},
                                                 {0.21, 0.0, NAN, true},
                                                 {0.39, 0.0, 0.2, false}}) {
    PoseCheck check;
    check.Check(RobotFromCamera(0.0), 0.0);
    const Eigen::Isometry3d next = Robot(step, 0.0, turn * deg) * RobotFromCamera(0.0);
    EXPECT_EQ(check.Check(next, time) != "", expect) << step << " m, " << turn << " deg";
  }
  PoseCheckOptions off;
  off.max_speed = 0.0;
  PoseCheck unchecked(off);
  unchecked.Check(RobotFromCamera(0.0), 0.0);
  EXPECT_EQ(unchecked.Check(Robot(5.0, 0.0, 0.0) * RobotFromCamera(0.0), 0.1), "");
}

// The sensor's pose passed as the robot's: the robot pose sits at the sensor's height with its
// tilt. The right robot pose (at the floor, level) and a sensor at the robot's origin (nothing
// to tell apart) raise nothing.
TEST(PoseCheck, TheSensorPosePassedAsTheRobotPoseIsReported) {
  const double deg = M_PI / 180.0;
  Eigen::Isometry3d sensor = Eigen::Isometry3d::Identity();  // MRPT's sensorPose: x forward, z up
  sensor.linear() = Eigen::AngleAxisd(16 * deg, Eigen::Vector3d::UnitY()).toRotationMatrix();
  sensor.translation() << 0.1, 0.0, 1.1;
  const Eigen::Isometry3d robot = Robot(2.0, 1.0, 0.7);
  const Eigen::Isometry3d camera = RobotFromCamera(16 * deg);  // where the check looks anyway
  EXPECT_EQ(PoseCheck().Check(camera, 0.0, PoseCheck::Mount{robot, sensor}), "");
  EXPECT_NE(PoseCheck()
                .Check(camera, 0.0, PoseCheck::Mount{robot * sensor, sensor})
                .find("robot + sensorPose passed as the robot pose?"),
            std::string::npos);
  EXPECT_EQ(PoseCheck().Check(camera, 0.0, PoseCheck::Mount{robot, Eigen::Isometry3d::Identity()}),
            "");
}

// Each limit is range-checked when read from an .ini; negative limits are refused.
// A hand-held camera looking down at a table 0.3 m below the floor's level of the world it was
// recorded in (TUM's motion capture puts z = 0 anywhere): the tilt and height checks are a ground
// robot's, the speed check stays; a fixed camera is told only that it moved.
TEST(PoseCheck, ThePlatformChoosesTheChecks) {
  Eigen::Isometry3d down = Robot(0, 0, 0) * RobotFromCamera(80.0 * M_PI / 180.0);
  down.translation().z() = -0.3;
  Eigen::Isometry3d far = down;
  far.translation().x() += 5.0;  // 5 m in 0.1 s
  PoseCheck robot;
  EXPECT_NE(robot.Check(down, 0.0).find("tilted 80 deg"), std::string::npos);
  PoseCheckOptions hand;
  hand.platform = CameraPlatform::kHandHeld;
  PoseCheck hand_held(hand);
  EXPECT_EQ(hand_held.Check(down, 0.0), "");
  EXPECT_NE(hand_held.Check(far, 0.1).find("camera moved 5.00 m"), std::string::npos);
  PoseCheckOptions fixed;
  fixed.platform = CameraPlatform::kFixed;
  PoseCheck fixed_camera(fixed);
  EXPECT_EQ(fixed_camera.Check(down, 0.0), "");
  Eigen::Isometry3d nudged = down;
  nudged.translation().y() += 0.005;  // 5 mm: within 1 cm
  EXPECT_EQ(fixed_camera.Check(nudged, 10.0), "");
  EXPECT_NE(fixed_camera.Check(far, 20.0).find("a fixed camera moved 5.000 m"), std::string::npos);
  EXPECT_EQ(fixed_camera.warnings(), 1);
  // From an .ini, by name.
  PoseCheckOptions read;
  PoseCheckOptionTable().Load(mrpt::config::CConfigFileMemory("[s]\nplatform = hand-held\n"), "s",
                              "test.ini", read);
  EXPECT_EQ(read.platform, CameraPlatform::kHandHeld);
}

TEST(PoseCheck, NegativeLimitsAreRefused) {
  for (const char* key :
       {"max_speed", "max_turn_rate_deg", "max_tilt_deg", "sensor_pose_tolerance"}) {
    PoseCheckOptions o;
    EXPECT_THROW(PoseCheckOptionTable().Load(
                     mrpt::config::CConfigFileMemory(std::string("[p]\n") + key + " = -1\n"), "p",
                     "t.ini", o),
                 std::runtime_error)
        << key;
  }
}

}  // namespace
}  // namespace novelty::mrpt_plugins
