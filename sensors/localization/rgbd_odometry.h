// Visual odometry for RGB-D sequences without poses (an importer's fallback, issue 51): OpenCV's
// RGB-D odometry (contrib rgbd module, RgbdICPOdometry: the photometric error of Steinbrücker et
// al., ICCV 2011, and the point-to-plane ICP error of KinectFusion, minimised together) between
// each frame and the last one tracked, the steps chained from an initial pose. The stereo rigs'
// odometry (direct_odometry.h) makes its own depth; here the sensor gives it. Measured on the 57
// steps of ../shared/data/tum-fr3-cabinet (keyframes 0.1–0.2 m apart, against motion capture):
// median step error 1.1 cm, 90th percentile 5.9 cm, against 7.3 / 21.5 cm for the photometric
// error alone (RgbdOdometry) and 4.2 / 15.2 cm for ICP alone. Drift accumulates with every step.
#pragma once

#include <Eigen/Geometry>
#include <memory>
#include <opencv2/core.hpp>
#include <optional>
#include <string>

#include "core/eigen_abi.h"
#include "core/pinhole_camera.h"

namespace novelty::sensors {

struct RgbdOdometryOptions {
  /// A step that moves the camera farther (m) or turns it more (degrees) between two frames is
  /// refused as a failure: hand-held sequences' keyframes are up to 0.5 m apart.
  double max_translation = 0.5;
  double max_rotation_deg = 30.0;
  /// Depth outside [min_depth, max_depth] (m) is not used: a Kinect's range.
  double min_depth = 0.3, max_depth = 6.0;
};

class RgbdOdometry {
 public:
  /// Throws std::invalid_argument for a bad camera or option.
  RgbdOdometry(const core::PinholeCamera& camera, const RgbdOdometryOptions& options = {},
               const Eigen::Isometry3d& initial_pose = Eigen::Isometry3d::Identity());
  ~RgbdOdometry();
  /// T_world_cam of a frame (`rgb` CV_8UC3, `depth` CV_32FC1 metres of the camera's size, 0
  /// unknown): the initial pose for the first, else the last tracked frame's moved by the step
  /// between them. nullopt with the reason when the step fails; the next frame is then tracked
  /// from the last tracked one. Throws std::invalid_argument for images of another size or type.
  std::optional<Eigen::Isometry3d> Track(const cv::Mat& rgb, const cv::Mat& depth,
                                         std::string* why);

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace novelty::sensors
