#include "mrpt_plugins/rawlog_map_player.h"

#include <mrpt/obs/CObservation3DRangeScan.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CObservationRobotPose.h>
#include <mrpt/obs/CObservationStereoImages.h>
#include <mrpt/poses/CPose3D.h>

#include <filesystem>
#include <limits>
#include <optional>
#include <stdexcept>

#include "sensors/rawlog/brief_message.h"
#include "sensors/rawlog/camera_pose_observation.h"
#include "sensors/rawlog/external_files.h"
#include "sensors/rawlog/rawlog_input.h"
#include "sensors/rawlog/rgbd_observation.h"

namespace novelty::mrpt_plugins {

namespace {

// T_robot_cam of the camera whose frames the maps take from `obs` (the left one of a pair), as
// the maps decode it.
Eigen::Isometry3d CameraOnRobotOf(const mrpt::obs::CObservation& obs) {
  if (const auto* scan = dynamic_cast<const mrpt::obs::CObservation3DRangeScan*>(&obs))
    return sensors::CameraOnRobot(*scan);
  const auto& pair = dynamic_cast<const mrpt::obs::CObservationStereoImages&>(obs);
  return sensors::ToEigen(mrpt::poses::CPose3D(pair.cameraPose));
}

}  // namespace

PoseSource ParsePoseSource(const std::string& text) {
  if (text == "groundtruth") return PoseSource::kGroundTruth;
  if (text == "rawlog") return PoseSource::kRawlog;
  if (text == "odometry") return PoseSource::kOdometry;
  throw std::invalid_argument("pose source '" + text +
                              "': expected groundtruth, rawlog or odometry");
}

class RawlogMapPlayer::Impl {
 public:
  Impl(const std::string& path, PoseSource s, std::map<int, Eigen::Isometry3d> poses)
      : input(path), source(s), camera_poses(std::move(poses)) {}
  sensors::RawlogInput input;
  PoseSource source;
  std::map<int, Eigen::Isometry3d> camera_poses;
  mrpt::obs::CObservationRobotPose::Ptr last_pose;
  std::optional<mrpt::poses::CPose3D> odometry;
  int frames = 0;
  int first = 1, last = std::numeric_limits<int>::max();  // SetFrameRange

  // The robot pose for camera observation `obs`, frame `frame`, from the chosen source.
  std::optional<mrpt::poses::CPose3D> RobotPose(const mrpt::obs::CObservation& obs,
                                                int frame) const {
    switch (source) {
      case PoseSource::kGroundTruth: {
        const auto it = camera_poses.find(frame);
        if (it == camera_poses.end()) return std::nullopt;
        // The robot pose that puts the camera there.
        return sensors::ToMrpt(it->second * CameraOnRobotOf(obs).inverse());
      }
      case PoseSource::kRawlog:
        if (!last_pose || last_pose->timestamp != obs.timestamp) return std::nullopt;
        return sensors::ToMrpt(sensors::RobotPoseOf(*last_pose));
      case PoseSource::kOdometry:
        return odometry;
    }
    return std::nullopt;
  }
};

RawlogMapPlayer::RawlogMapPlayer(const std::string& rawlog, PoseSource source,
                                 std::map<int, Eigen::Isometry3d> camera_poses)
    : impl_(std::make_unique<Impl>(rawlog, source, std::move(camera_poses))) {}

RawlogMapPlayer::~RawlogMapPlayer() = default;

void RawlogMapPlayer::SetFrameRange(int first, int last) {
  if (first < 1 || last < first)
    throw std::invalid_argument("RawlogMapPlayer: frames " + std::to_string(first) + "-" +
                                std::to_string(last) + " are no range of 1-based frames");
  impl_->first = first;
  impl_->last = last;
}

bool RawlogMapPlayer::Next(mrpt::maps::CMultiMetricMap& maps, int& frame) {
  Impl& m = *impl_;
  while (true) {
    mrpt::serialization::CSerializable::Ptr object;
    try {
      object = m.input.Next();
    } catch (const std::exception& e) {  // a rawlog cut short: what was read stays
      stopped_by_ = e.what();
      return false;
    }
    if (!object) return false;
    if (auto pose = std::dynamic_pointer_cast<mrpt::obs::CObservationRobotPose>(object)) {
      m.last_pose = pose;
      continue;
    }
    if (auto odo = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(object)) {
      m.odometry = mrpt::poses::CPose3D(odo->odometry);
      continue;
    }
    auto obs = std::dynamic_pointer_cast<mrpt::obs::CObservation>(object);
    const bool camera = std::dynamic_pointer_cast<mrpt::obs::CObservation3DRangeScan>(object) ||
                        std::dynamic_pointer_cast<mrpt::obs::CObservationStereoImages>(object);
    if (!obs || !camera) continue;
    if (m.frames >= m.last) return false;
    frame = ++m.frames;
    if (frame < m.first) continue;
    const std::string where =
        m.input.path() + ": frame " + std::to_string(frame) + " (" + obs->sensorLabel + ")";
    sensors::CheckImageFolder(*obs, where);
    const std::optional<mrpt::poses::CPose3D> robot = m.RobotPose(*obs, frame);
    if (!robot) {
      skip_reasons_.push_back(where + ": no pose");
      continue;
    }
    try {
      sensors::CheckExternalDepth(*obs);
      obs->load();  // once for all the maps that decode it; unloaded when they are done
      if (before_insert_) before_insert_(frame);
      const bool used = maps.insertObservation(*obs, *robot);
      obs->unload();
      if (!used) {
        skip_reasons_.push_back(where + ": no map used it");
        continue;
      }
      return true;
    } catch (const std::exception& e) {
      obs->unload();
      skip_reasons_.push_back(where + ": " + sensors::BriefMessage(e));
    }
  }
}

}  // namespace novelty::mrpt_plugins
