// Warnings for camera poses a robot cannot have. insertObservation(obs, robot_pose) places the
// camera at robot_pose ⊕ obs.sensorPose; a program that passes the camera's pose instead applies
// the sensor pose twice, and the map silently gets fewer views and more surprise. Such poses
// usually show: the camera ends up steeply tilted or rolled (looking into the floor), below the
// floor, or it jumps between frames farther than a robot moves; or the robot pose itself sits at
// the sensor's height with the sensor's tilt (it is robot ⊕ sensorPose, a ground robot's pose is
// at the floor and level). Each is reported, never refused. What is implausible depends on what
// carries the camera (`platform`): a ground robot gets every check, a hand-held camera only the
// speed and turn checks (a hand tilts and lowers it anywhere), a fixed camera a warning whenever
// it moves; a limit or tolerance of 0 turns its check off.
#pragma once

#include <Eigen/Geometry>
#include <functional>
#include <optional>
#include <string>

#include "core/eigen_abi.h"
#include "mrpt_plugins/option_table.h"

namespace novelty::mrpt_plugins {

enum class CameraPlatform { kGroundRobot, kHandHeld, kFixed };

struct PoseCheckOptions {
  /// What carries the camera: which checks apply (ground-robot: all; hand-held: max_speed and
  /// max_turn_rate; fixed: a move of more than 1 cm or 1 degree from the first pose).
  CameraPlatform platform = CameraPlatform::kGroundRobot;
  /// m/s; consecutive frames farther apart than this allows (over their time difference, at
  /// least 0.1 s) are a jump. A Pioneer 3-DX drives at most 1.2 m/s.
  double max_speed = 2.0;
  /// rad/s; the same for the camera's turn.
  double max_turn_rate = M_PI;
  /// rad; the image's up direction farther than this from the world's +Z (MRPT: z up) is a
  /// camera looking steeply down into the floor, or rolled.
  double max_tilt = 60.0 * M_PI / 180.0;
  /// m; a camera centre lower than this is below the floor (the world's z = 0).
  double min_height = -0.05;
  /// m; a robot pose within this of the sensor's height on the robot, and tilted like the sensor
  /// (within 2 degrees), is the sensor's pose passed as the robot's. Only for sensors mounted at
  /// least 5 cm up or tilted at least 3 degrees (others cannot be told apart).
  double sensor_pose_tolerance = 0.02;
};

/// platform, max_speed, max_turn_rate_deg, max_tilt_deg, min_height, sensor_pose_tolerance.
const OptionTable<PoseCheckOptions>& PoseCheckOptionTable();

class PoseCheck {
 public:
  explicit PoseCheck(const PoseCheckOptions& options = {}) : options_(options) {}

  /// Where the camera came from: the robot pose given and the sensor's pose on the robot (MRPT's
  /// sensorPose), for observations inserted with insertObservation.
  struct Mount {
    Eigen::Isometry3d robot;
    Eigen::Isometry3d sensor_on_robot;
  };

  /// Checks the camera pose T_world_cam (camera +Z forward, +Y down) of the frame at `time`
  /// (seconds; NaN if unknown) against the last one, and the robot pose it came from (if
  /// `mount`); returns what is implausible ("" if nothing), in one line for a log.
  std::string Check(const Eigen::Isometry3d& T_world_cam, double time,
                    const std::optional<Mount>& mount = std::nullopt);
  /// Forget the last pose (a new run, a cleared map).
  void Reset() { last_.reset(), first_.reset(); }

  int warnings() const { return warnings_; }
  const PoseCheckOptions& options() const { return options_; }

 private:
  struct Last {
    Eigen::Isometry3d T_world_cam;
    double time;
  };
  void AddGroundRobotProblems(const Eigen::Isometry3d& T_world_cam,
                              const std::optional<Mount>& mount,
                              const std::function<void(const std::string&)>& add) const;

  PoseCheckOptions options_;
  std::optional<Last> last_;
  std::optional<Eigen::Isometry3d> first_;  // a fixed camera's pose
  int warnings_ = 0;
};

}  // namespace novelty::mrpt_plugins
