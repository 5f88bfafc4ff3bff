#include "mrpt_plugins/observation_frame.h"

#include <mrpt/obs/CObservation3DRangeScan.h>

#include <stdexcept>

#include "sensors/rawlog/rgbd_observation.h"

namespace novelty::mrpt_plugins {

bool DecodeObservation(const mrpt::obs::CObservation& obs,
                       const std::optional<const mrpt::poses::CPose3D>& robot, core::Frame& frame) {
  const auto* scan = dynamic_cast<const mrpt::obs::CObservation3DRangeScan*>(&obs);
  if (!scan) return false;
  scan->load();
  try {
    sensors::DecodeRgbd(*scan, frame.rgb, frame.depth, frame.camera);
  } catch (const std::exception& e) {
    throw std::invalid_argument("observation '" + scan->sensorLabel + "': " + e.what());
  }
  const Eigen::Isometry3d world_from_robot =
      robot ? sensors::ToEigen(*robot) : Eigen::Isometry3d::Identity();
  frame.T_world_cam = world_from_robot * sensors::CameraOnRobot(*scan);
  return true;
}

}  // namespace novelty::mrpt_plugins
