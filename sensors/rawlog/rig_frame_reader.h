// Reads multi-camera frames from an MRPT rawlog: a CObservationStereoImages (left camera is the
// reference) or a trinocular triple of CObservationImage labelled CAM_CENTER, CAM_LEFT and
// CAM_RIGHT with one timestamp (centre camera is the reference), as novelty-sim writes them and
// as a Bumblebee XB3 driver would. Everything else in the rawlog is handed back untouched so a
// converter can copy it through in order. An incomplete triple, images of different sizes in one
// rig, or an image that cannot be loaded skips the frame and counts it with its reason.
#pragma once

#include <mrpt/obs/CObservationStereoImages.h>

#include <mrpt/serialization/CSerializable.h>

#include <Eigen/Geometry>
#include <memory>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "core/eigen_abi.h"
#include "core/pinhole_camera.h"

namespace novelty::sensors {

struct RigFrame {
  int index = 0;      ///< 1-based among the rawlog's rig frames (skipped ones included)
  double time = 0.0;  ///< seconds since the Unix epoch
  /// Images CV_8UC3 R G B, reference camera first.
  std::vector<cv::Mat> images;
  std::vector<core::PinholeCamera> cameras;
  /// T_ref_cam of each camera (identity for the reference).
  std::vector<Eigen::Isometry3d> ref_from_camera;
  /// T_robot_ref: where the reference camera sits on the robot (+Z forward).
  Eigen::Isometry3d robot_from_reference = Eigen::Isometry3d::Identity();
};

/// One CObservationStereoImages as a rig frame (left camera the reference); loads its external
/// images and unloads them again. Throws std::runtime_error without a right image.
RigFrame RigFrameFromStereo(mrpt::obs::CObservationStereoImages& obs);

class RigFrameReader {
 public:
  /// Opens `path`; throws std::runtime_error naming it if it cannot be opened.
  explicit RigFrameReader(const std::string& path);
  ~RigFrameReader();

  /// The next complete rig frame; false at the end. Objects that are not rig images, read since
  /// the previous call, are appended to `others` (may be null) in file order.
  bool Next(RigFrame& frame, std::vector<mrpt::serialization::CSerializable::Ptr>* others);
  int skipped() const { return static_cast<int>(skip_reasons_.size()); }
  const std::vector<std::string>& skip_reasons() const { return skip_reasons_; }

 private:
  class Impl;
  std::unique_ptr<Impl> impl_;
  std::vector<std::string> skip_reasons_;
};

}  // namespace novelty::sensors
