// Puts camera poses into a rawlog: a copy of it with a CObservationRobotPose
// (camera_pose_observation.h) just before every camera observation that got a pose — what
// novelty-poses writes and novelty-run --poses rawlog reads. The poses come from a function of
// the observation's time (a tracker's interpolated trajectory, visual localization's poses by
// timestamp); a camera observation without one is copied as it is and its reason kept.
#pragma once

#include <Eigen/Geometry>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/eigen_abi.h"

namespace novelty::sensors {

/// T_world_cam at `time` (s), or nullopt with the reason in `*why`.
using CameraPoseAt = std::function<std::optional<Eigen::Isometry3d>(double time, std::string* why)>;

struct CameraPoseAnnotation {
  int cameras = 0;                   ///< camera observations (RGB-D, image, stereo) in the input
  int posed = 0;                     ///< of them, those that got a pose
  std::vector<std::string> reasons;  ///< why each of the others got none, in order
  /// Every camera time (a rig's images share one) with its pose if it got one: in time order
  /// they are the frames 1, 2, … of novelty-sim's ground truth.
  std::map<double, std::optional<Eigen::Isometry3d>> poses;
};

/// Copies `input` to `output` (written atomically, images shared with the input's folder) with
/// the poses `pose_at` gives, labelled `label` ("POSE_TRACKER"), with the uncertainty
/// `std_position` (m) and `std_angle` (rad). Throws std::runtime_error naming the file.
CameraPoseAnnotation AnnotateCameraPoses(const std::string& input, const std::string& output,
                                         const CameraPoseAt& pose_at, const std::string& label,
                                         double std_position = 0.001, double std_angle = 0.003);

}  // namespace novelty::sensors
