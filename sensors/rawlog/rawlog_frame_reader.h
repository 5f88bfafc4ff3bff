// Reads camera frames from an MRPT rawlog (observations format, as novelty-sim writes and MRPT's
// tools read): each CObservation3DRangeScan with an intensity image becomes a Frame with RGB,
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

#include "maps/views/pinhole_camera.h"

namespace novelty::sensors {

struct Frame {
  int index = 0;      ///< 1-based among the rawlog's RGB-D observations
  double time = 0.0;  ///< seconds (MRPT timestamp as a double)
  std::string label;  ///< sensor label
  cv::Mat rgb;        ///< CV_8UC3 R G B
  cv::Mat depth;      ///< CV_32FC1 metres along +Z, 0 = unknown
  views::PinholeCamera camera;
  /// T_world_cam from a CObservationRobotPose with the frame's timestamp just before it
  /// (camera_pose_observation.h: novelty-poses), if there is one; its label in pose_source.
  std::optional<Eigen::Isometry3d> pose;
  std::string pose_source;
};

class RawlogFrameReader {
 public:
  /// Opens `path`; throws std::runtime_error naming it if it cannot be opened.
  explicit RawlogFrameReader(const std::string& path);
  ~RawlogFrameReader();

  /// The next RGB-D frame; false at the end of the rawlog.
  bool Next(Frame& frame);
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
