// One camera frame as every part passes it on: colour image, depth, intrinsics and, where known,
// the camera's pose. Rawlog and dataset readers make Frames, the maps' MRPT adapters decode
// observations into them, the apps hand them to the maps.
#pragma once

#include <Eigen/Geometry>
#include <opencv2/core.hpp>
#include <optional>
#include <string>

#include "core/eigen_abi.h"
#include "core/pinhole_camera.h"

namespace novelty::core {

struct Frame {
  int index = 0;      ///< 1-based number in its source (a rawlog's RGB-D frames, a folder)
  double time = 0.0;  ///< seconds (MRPT timestamp as a double); 0 where the source has none
  std::string label;  ///< the sensor's label, where the source names one
  cv::Mat rgb;        ///< CV_8UC3 R G B
  cv::Mat depth;      ///< CV_32FC1 metres along +Z; 0 or NaN = unknown
  PinholeCamera camera;
  /// T_world_cam, where the source gives it; pose_source says where it came from (a sensor
  /// label, "groundtruth", "robot pose ⊕ sensor pose", ...).
  std::optional<Eigen::Isometry3d> T_world_cam;
  std::string pose_source;
};

}  // namespace novelty::core
