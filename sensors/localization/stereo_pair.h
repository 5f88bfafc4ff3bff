// Two synchronised images of a calibrated rig: the reference camera (whose pose visual
// localization estimates) and another camera used to triangulate features (3.1.1: the left and
// right images of a stereo camera; of a trinocular rig, the centre and one side image).
#pragma once

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "core/eigen_abi.h"
#include "core/pinhole_camera.h"

namespace novelty::sensors {

struct StereoPair {
  double time = 0.0;
  cv::Mat reference, other;  ///< CV_8UC3 RGB or CV_8UC1, same size
  core::PinholeCamera reference_camera, other_camera;
  Eigen::Isometry3d reference_from_other = Eigen::Isometry3d::Identity();
};

/// Why `pair` cannot be used (an image missing, or the two of different sizes); empty if it can.
inline const char* StereoPairProblem(const StereoPair& pair) {
  if (pair.reference.empty() || pair.reference.size() != pair.other.size())
    return "stereo images missing or of different sizes";
  return "";
}

}  // namespace novelty::sensors
