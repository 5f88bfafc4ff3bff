// Warnings for camera poses a robot cannot have. insertObservation(obs, robot_pose) places the
// camera at robot_pose ⊕ obs.sensorPose; a program that passes the camera's pose instead applies
// the sensor pose twice, and the map silently gets fewer views and more surprise. Such poses
// usually show: the camera ends up steeply tilted or rolled (looking into the floor), below the
// floor, or it jumps between frames farther than a robot moves. Each is reported, never refused:
// a handheld or ceiling camera may be fine with it (set the limit to 0 to turn a check off).
#pragma once

#include <Eigen/Geometry>
#include <optional>
#include <string>

#include "mrpt_plugins/option_table.h"

namespace novelty::mrpt_plugins {

struct PoseCheckOptions {
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
};

/// max_speed, max_turn_rate_deg, max_tilt_deg, min_height.
const OptionTable<PoseCheckOptions>& PoseCheckOptionTable();

class PoseCheck {
 public:
  explicit PoseCheck(const PoseCheckOptions& options = {}) : options_(options) {}

  /// Checks the camera pose T_world_cam (camera +Z forward, +Y down) of the frame at `time`
  /// (seconds; NaN if unknown) against the last one; returns what is implausible ("" if
  /// nothing), in one line for a log.
  std::string Check(const Eigen::Isometry3d& T_world_cam, double time);
  /// Forget the last pose (a new run, a cleared map).
  void Reset() { last_.reset(); }

  int warnings() const { return warnings_; }
  const PoseCheckOptions& options() const { return options_; }

 private:
  struct Last {
    Eigen::Isometry3d T_world_cam;
    double time;
  };
  PoseCheckOptions options_;
  std::optional<Last> last_;
  int warnings_ = 0;
};

}  // namespace novelty::mrpt_plugins
