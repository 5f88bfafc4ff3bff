// Camera poses computed offline (from the LED tracker or from vision) stored in a rawlog as
// MRPT's CObservationRobotPose, written just before the camera observation they belong to, with
// its timestamp: the robot pose T_world_robot = T_world_cam · T_robot_cam⁻¹ (the camera's
// mounting from that observation), so MRPT's tools show the robot path and the camera pose is
// recovered exactly. The label names the source ("POSE_TRACKER", "POSE_VISUAL").
#pragma once

#include <mrpt/obs/CObservationRobotPose.h>

#include <Eigen/Geometry>
#include <string>

#include "core/eigen_abi.h"

namespace novelty::sensors {

/// `time`: seconds since the Unix epoch; `std_position`/`std_angle`: the pose's uncertainty
/// (m, rad), put on the covariance's diagonal.
mrpt::obs::CObservationRobotPose MakeCameraPoseObservation(
    double time, const Eigen::Isometry3d& world_from_camera,
    const Eigen::Isometry3d& robot_from_camera, const std::string& label, double std_position,
    double std_angle);

/// T_world_robot of such an observation.
Eigen::Isometry3d RobotPoseOf(const mrpt::obs::CObservationRobotPose& obs);

}  // namespace novelty::sensors
