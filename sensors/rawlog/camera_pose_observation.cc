#include "sensors/rawlog/camera_pose_observation.h"

#include "sensors/rawlog/rgbd_observation.h"

namespace novelty::sensors {

mrpt::obs::CObservationRobotPose MakeCameraPoseObservation(
    double time, const Eigen::Isometry3d& world_from_camera,
    const Eigen::Isometry3d& robot_from_camera, const std::string& label, double std_position,
    double std_angle) {
  mrpt::obs::CObservationRobotPose obs;
  obs.timestamp = mrpt::Clock::fromDouble(time);
  obs.sensorLabel = label;
  obs.pose.mean = ToMrpt(world_from_camera * robot_from_camera.inverse());
  obs.pose.cov.setZero();
  for (int i = 0; i < 3; ++i) {
    obs.pose.cov(i, i) = std_position * std_position;
    obs.pose.cov(i + 3, i + 3) = std_angle * std_angle;
  }
  return obs;
}

Eigen::Isometry3d RobotPoseOf(const mrpt::obs::CObservationRobotPose& obs) {
  return ToEigen(obs.pose.mean);
}

}  // namespace novelty::sensors
