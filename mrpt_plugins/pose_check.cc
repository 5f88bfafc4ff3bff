#include "mrpt_plugins/pose_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>

namespace novelty::mrpt_plugins {

namespace {

constexpr double kMinInterval = 0.1;  // s: timestamps closer than this (or none) count as 0.1 s

std::string Format(const char* format, double a, double b) {
  char text[256];
  std::snprintf(text, sizeof text, format, a, b);
  return text;
}

}  // namespace

const OptionTable<PoseCheckOptions>& PoseCheckOptionTable() {
  using O = PoseCheckOptions;
  static const OptionTable<O> table = [] {
    OptionTable<O> t;
    t.AddChoice(
         "platform", [](O & o) -> auto& { return o.platform; },
         {"ground-robot", "hand-held", "fixed"},
         "what carries the camera: ground-robot (every check), hand-held (speed and turn only), "
         "fixed (a warning when it moves)")
        .Add(
            "max_speed", [](O & o) -> auto& { return o.max_speed; },
            "m/s; a warning when the camera moves faster between frames (0 = no check)")
        .Add(
            "max_turn_rate_deg", [](O & o) -> auto& { return o.max_turn_rate; },
            "deg/s; ... or turns faster (0 = no check)", M_PI / 180.0)
        .Add(
            "max_tilt_deg", [](O & o) -> auto& { return o.max_tilt; },
            "deg; ... or its image's up is tilted more from the world's +z (0 = no check; "
            "ground-robot only)",
            M_PI / 180.0)
        .Add(
            "min_height", [](O & o) -> auto& { return o.min_height; },
            "m; ... or it is lower (below the floor, z = 0; ground-robot only)")
        .Add(
            "sensor_pose_tolerance", [](O & o) -> auto& { return o.sensor_pose_tolerance; },
            "m; ... or the robot pose is at the sensor's height on the robot (0 = no check; "
            "ground-robot only)")
        .Check([](const O& o) {
          CheckNotNegative(o.max_speed, "max_speed");
          CheckNotNegative(o.max_turn_rate, "max_turn_rate_deg");
          CheckNotNegative(o.max_tilt, "max_tilt_deg");
          CheckNotNegative(o.sensor_pose_tolerance, "sensor_pose_tolerance");
          if (!std::isfinite(o.min_height))
            throw std::invalid_argument("min_height must be finite");
        });
    return t;
  }();
  return table;
}

namespace {

// Angle (rad) between a direction and the +z (up) of the frame it is expressed in.
double AngleFromUp(const Eigen::Vector3d& direction) {
  return std::acos(std::clamp(direction.z() / direction.norm(), -1.0, 1.0));
}
// How far a frame's own z axis is tilted.
double Tilt(const Eigen::Isometry3d& pose) {
  return AngleFromUp(pose.linear().col(2));
}

}  // namespace

void PoseCheck::AddGroundRobotProblems(const Eigen::Isometry3d& T_world_cam,
                                       const std::optional<Mount>& mount,
                                       const std::function<void(const std::string&)>& add) const {
  const double tilt = AngleFromUp(-T_world_cam.linear().col(1));  // image up: camera -Y
  if (options_.max_tilt > 0 && tilt > options_.max_tilt)
    add(Format("camera tilted %.0f deg from upright (limit %.0f deg)", tilt * 180 / M_PI,
               options_.max_tilt * 180 / M_PI));
  if (T_world_cam.translation().z() < options_.min_height)
    add(Format("camera %.2f m below the floor (limit %.2f m)", -T_world_cam.translation().z(),
               -options_.min_height));
  if (!mount || options_.sensor_pose_tolerance <= 0) return;
  const double sensor_height = mount->sensor_on_robot.translation().z(),
               sensor_tilt = Tilt(mount->sensor_on_robot);
  const bool distinct = std::abs(sensor_height) >= 0.05 || sensor_tilt >= 3.0 * M_PI / 180.0;
  if (distinct &&
      std::abs(mount->robot.translation().z() - sensor_height) <= options_.sensor_pose_tolerance &&
      std::abs(Tilt(mount->robot) - sensor_tilt) <= 2.0 * M_PI / 180.0)
    add(
        Format("the robot pose is at the sensor's height (%.2f m) and tilt (%.0f deg): "
               "robot + sensorPose passed as the robot pose?",
               sensor_height, sensor_tilt * 180 / M_PI));
}

namespace {

// A fixed camera: any move from where it was first seen.
std::string FixedCameraProblem(const Eigen::Isometry3d& first, const Eigen::Isometry3d& now) {
  const double shift = (now.translation() - first.translation()).norm();
  const double turn = Eigen::AngleAxisd(first.linear().transpose() * now.linear()).angle();
  if (shift <= 0.01 && turn <= M_PI / 180.0) return "";
  return Format("a fixed camera moved %.3f m and turned %.1f deg from its first pose", shift,
                turn * 180 / M_PI);
}

}  // namespace

std::string PoseCheck::Check(const Eigen::Isometry3d& T_world_cam, double time,
                             const std::optional<Mount>& mount) {
  if (options_.platform == CameraPlatform::kFixed) {
    if (!first_) first_ = T_world_cam;
    const std::string problem = FixedCameraProblem(*first_, T_world_cam);
    if (!problem.empty()) ++warnings_;
    return problem;
  }
  std::string problems;
  const auto add = [&problems](const std::string& p) {
    problems += (problems.empty() ? "" : "; ") + p;
  };
  if (options_.platform == CameraPlatform::kGroundRobot)
    AddGroundRobotProblems(T_world_cam, mount, add);
  if (last_) {
    const double dt = std::isfinite(time) && std::isfinite(last_->time)
                          ? std::max(std::abs(time - last_->time), kMinInterval)
                          : kMinInterval;
    const double step = (T_world_cam.translation() - last_->T_world_cam.translation()).norm();
    const double turn =
        Eigen::AngleAxisd(last_->T_world_cam.linear().transpose() * T_world_cam.linear()).angle();
    if (options_.max_speed > 0 && step > options_.max_speed * dt)
      add(Format("camera moved %.2f m in %.2f s", step, dt));
    if (options_.max_turn_rate > 0 && turn > options_.max_turn_rate * dt)
      add(Format("camera turned %.0f deg in %.2f s", turn * 180 / M_PI, dt));
  }
  last_ = Last{T_world_cam, time};
  if (!problems.empty()) ++warnings_;
  return problems;
}

}  // namespace novelty::mrpt_plugins
