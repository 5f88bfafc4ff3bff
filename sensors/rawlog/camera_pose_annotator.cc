#include "sensors/rawlog/camera_pose_annotator.h"

#include <mrpt/obs/CObservation3DRangeScan.h>
#include <mrpt/obs/CObservationImage.h>
#include <mrpt/obs/CObservationStereoImages.h>

#include "sensors/rawlog/camera_pose_observation.h"
#include "sensors/rawlog/rawlog_input.h"
#include "sensors/rawlog/rawlog_output.h"
#include "sensors/rawlog/rgbd_observation.h"

namespace novelty::sensors {
namespace {

// T_robot_cam of a camera observation, or nullopt for anything else.
std::optional<Eigen::Isometry3d> CameraMount(const mrpt::serialization::CSerializable& obj) {
  if (auto* scan = dynamic_cast<const mrpt::obs::CObservation3DRangeScan*>(&obj))
    return CameraOnRobot(*scan);
  if (auto* image = dynamic_cast<const mrpt::obs::CObservationImage*>(&obj))
    return ToEigen(image->cameraPose);
  if (auto* stereo = dynamic_cast<const mrpt::obs::CObservationStereoImages*>(&obj))
    return ToEigen(mrpt::poses::CPose3D(stereo->cameraPose));
  return std::nullopt;
}

}  // namespace

CameraPoseAnnotation AnnotateCameraPoses(const std::string& input, const std::string& output,
                                         const CameraPoseAt& pose_at, const std::string& label,
                                         double std_position, double std_angle) {
  RawlogInput in(input);
  RawlogOutput out(output);
  out.ShareImagesOf(input);
  CameraPoseAnnotation a;
  while (const auto obj = in.Next()) {
    if (const auto mount = CameraMount(*obj)) {
      ++a.cameras;
      const double t =
          mrpt::Clock::toDouble(dynamic_cast<const mrpt::obs::CObservation&>(*obj).timestamp);
      std::string why;
      const auto pose = pose_at(t, &why);
      if (pose) {
        out.Write(MakeCameraPoseObservation(t, *pose, *mount, label, std_position, std_angle));
        ++a.posed;
      } else {
        a.reasons.push_back(why);
      }
      a.poses.emplace(t, pose);
    }
    out.Write(*obj);
  }
  out.Close();
  return a;
}

}  // namespace novelty::sensors
