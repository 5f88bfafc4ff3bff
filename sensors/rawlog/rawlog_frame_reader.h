// Reads camera frames from an MRPT rawlog (observations format, as novelty-sim writes and MRPT's
// tools read): each CObservation3DRangeScan with an intensity image becomes a core::Frame with RGB,
// depth in metres and intrinsics. Externally stored images are looked up in MRPT's
// `<name>_Images/` folder beside the rawlog. Poses come separately (ground truth:
// sim/output/ground_truth_reader.h; tracker).
// A CObservationRobotPose with the same timestamp before a frame gives its camera pose
// (camera_pose_observation.h). Observations of other kinds are passed over; a range scan that
// cannot be loaded or is inconsistent is skipped and counted, with the reason kept for the log.
#pragma once

#include <Eigen/Geometry>
#include <map>
#include <memory>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/eigen_abi.h"
#include "core/frame.h"

namespace novelty::sensors {

class RawlogFrameReader {
 public:
  /// Opens `path`; throws std::runtime_error naming it if it cannot be opened.
  explicit RawlogFrameReader(const std::string& path);
  ~RawlogFrameReader();

  /// The next RGB-D frame; false at the end of the rawlog.
  bool Next(core::Frame& frame);
  int skipped() const { return static_cast<int>(skip_reasons_.size()); }
  const std::vector<std::string>& skip_reasons() const { return skip_reasons_; }

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
  std::string path_;
  int frames_ = 0;
  std::vector<std::string> skip_reasons_;
};

}  // namespace novelty::sensors
