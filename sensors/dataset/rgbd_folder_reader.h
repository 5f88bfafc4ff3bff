// Reads RGB-D frames stored as a folder in the ICL-NUIM layout:
//   color/N.png  RGB (8-bit),  depth/N.png  16-bit depth (metres = value / depth_scale),
//   pose.txt     one line per frame "tx ty tz qx qy qz qw", T_world_cam (p_world = R p_cam + t).
// Frames are numbered from 1 in the order of pose.txt's lines.
#pragma once

#include <Eigen/Geometry>
#include <opencv2/core.hpp>
#include <string>

#include "core/eigen_abi.h"
#include "core/frame.h"
#include "core/pinhole_camera.h"

namespace novelty::sensors {

class RgbdFolderReader {
 public:
  /// Throws std::runtime_error naming the folder if pose.txt is missing or malformed (the line).
  RgbdFolderReader(const std::string& folder, const core::PinholeCamera& camera,
                   double depth_scale);
  int size() const { return static_cast<int>(poses_.size()); }
  /// Frame `index` (1-based). Throws std::runtime_error naming the file that is missing, has the
  /// wrong size or type.
  core::Frame Read(int index) const;
  const core::PinholeCamera& camera() const { return camera_; }

 private:
  std::string folder_;
  core::PinholeCamera camera_;
  double depth_scale_;
  std::vector<Eigen::Isometry3d> poses_;
};

}  // namespace novelty::sensors
