// Plays an MRPT rawlog into a CMultiMetricMap, as an MRPT program would: every camera
// observation (CObservation3DRangeScan, and what the maps' depth source accepts) goes to
// insertObservation(obs, robot pose). The robot pose comes from, by option:
//   kRawlog       the CObservationRobotPose with the observation's timestamp written just before
//                 it (novelty-poses; sensors/rawlog/camera_pose_observation.h);
//   kOdometry     the latest CObservationOdometry (wheel odometry: drifts);
//   kGroundTruth  a camera pose per frame (novelty-sim's groundtruth/poses.csv), turned into the
//                 robot pose the observation's sensor pose composes it with.
// Frames are numbered 1, 2, … over the rawlog's RGB-D observations, as the ground truth is. A frame
// without a pose, or one the maps reject (an unusable scan), is skipped and counted with its
// reason; a rawlog cut short ends the play, keeping what was read.
#pragma once

#include <mrpt/maps/CMultiMetricMap.h>
#include <mrpt/obs/CObservation.h>

#include <Eigen/Geometry>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "core/eigen_abi.h"

namespace novelty::mrpt_plugins {

enum class PoseSource { kGroundTruth, kRawlog, kOdometry };

/// "groundtruth", "rawlog", "odometry"; throws std::invalid_argument naming the text otherwise.
PoseSource ParsePoseSource(const std::string& text);

class RawlogMapPlayer {
 public:
  /// Opens `rawlog`; `camera_poses`: T_world_cam per frame for kGroundTruth (else unused).
  /// Throws std::runtime_error naming the file if it cannot be opened.
  RawlogMapPlayer(const std::string& rawlog, PoseSource source,
                  std::map<int, Eigen::Isometry3d> camera_poses = {});
  ~RawlogMapPlayer();

  /// Inserts the next camera frame into `maps`; false at the end of the rawlog. `frame`
  /// receives its 1-based number. A frame that cannot be used is skipped (skip_reasons); an
  /// image folder that does not exist throws std::runtime_error naming it.
  bool Next(mrpt::maps::CMultiMetricMap& maps, int& frame);

  /// Plays only frames first…last (1-based, as Next numbers them): the others are read past, not
  /// inserted and not counted as skipped, and the play ends after `last` (one lighting's pass in a
  /// rawlog of several). Throws std::invalid_argument unless 1 ≤ first ≤ last.
  void SetFrameRange(int first, int last);

  /// Called with a frame's number just before it goes into the maps (not for frames skipped
  /// before that), so that what a frame number decides — a map paused or learning — follows the
  /// frame actually inserted, however many were skipped before it.
  void SetBeforeInsert(std::function<void(int frame)> hook) { before_insert_ = std::move(hook); }

  int skipped() const { return int(skip_reasons_.size()); }
  const std::vector<std::string>& skip_reasons() const { return skip_reasons_; }
  /// Why the play ended early (a truncated rawlog), or empty.
  const std::string& stopped_by() const { return stopped_by_; }

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
  std::vector<std::string> skip_reasons_;
  std::string stopped_by_;
  std::function<void(int frame)> before_insert_;
};

}  // namespace novelty::mrpt_plugins
