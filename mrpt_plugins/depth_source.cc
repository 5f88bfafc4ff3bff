#include "mrpt_plugins/depth_source.h"

#include <mrpt/obs/CObservationStereoImages.h>

#include <stdexcept>

#include "sensors/rawlog/rgbd_observation.h"
#include "sensors/rawlog/rig_frame_reader.h"

namespace novelty::mrpt_plugins {

bool DecodeWithDepthSource(const mrpt::obs::CObservation& obs,
                           const std::optional<const mrpt::poses::CPose3D>& robot_pose,
                           const DepthSourceOptions& options, core::Frame& frame) {
  if (options.kind != DepthSourceOptions::Kind::kStereo) return false;
  const auto* stereo = dynamic_cast<const mrpt::obs::CObservationStereoImages*>(&obs);
  if (!stereo) return false;
  sensors::RigFrame rig;
  try {
    // load() fills the external images: a copy, so the caller's observation stays as it was.
    mrpt::obs::CObservationStereoImages copy(*stereo);
    rig = sensors::RigFrameFromStereo(copy);
    std::vector<sensors::SweepView> others{{rig.images[1], rig.cameras[1], rig.ref_from_camera[1]}};
    frame.depth =
        sensors::ComputeStereoDepth(rig.images[0], rig.cameras[0], others, options.stereo).depth;
  } catch (const std::exception& e) {
    throw std::invalid_argument("stereo observation '" + stereo->sensorLabel + "': " + e.what());
  }
  frame.rgb = rig.images[0];
  frame.camera = rig.cameras[0];
  const Eigen::Isometry3d world_from_robot =
      robot_pose ? sensors::ToEigen(*robot_pose) : Eigen::Isometry3d::Identity();
  frame.T_world_cam = world_from_robot * rig.robot_from_reference;
  return true;
}

}  // namespace novelty::mrpt_plugins
