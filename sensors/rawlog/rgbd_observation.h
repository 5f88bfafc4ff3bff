// RGB-D frames ⇄ MRPT's CObservation3DRangeScan, as novelty-sim writes them and the maps read
// them: range_is_depth, rangeUnits 0.2 mm, intensity image with the same intrinsics, sensorPose in
// MRPT's 3D-scan frame (+X forward, +Y left, +Z up) — the camera frame (+Z forward, +X right,
// +Y down) turned accordingly.
#pragma once

#include <mrpt/obs/CObservation3DRangeScan.h>

#include <Eigen/Geometry>
#include <opencv2/core.hpp>
#include <string>

#include "core/eigen_abi.h"
#include "core/pinhole_camera.h"

namespace novelty::sensors {

/// The depth a range image holds: 0.2 mm steps in 16 bits (depth beyond is stored as this).
inline constexpr float kRgbdRangeUnits = 0.0002f;
inline constexpr float kRgbdMaxDepth = 65535 * kRgbdRangeUnits;  // 13.107 m

/// An observation holding the images in memory. `time` is seconds since the Unix epoch.
mrpt::obs::CObservation3DRangeScan MakeRgbdObservation(double time, const cv::Mat& rgb,
                                                       const cv::Mat& depth,
                                                       const core::PinholeCamera& camera,
                                                       const Eigen::Isometry3d& robot_from_camera);

/// T_robot_cam of the observation's colour camera (+Z forward).
Eigen::Isometry3d CameraOnRobot(const mrpt::obs::CObservation3DRangeScan& obs);

/// Decoded images and intrinsics; the observation must be loaded. Throws std::runtime_error
/// saying what is missing or inconsistent.
void DecodeRgbd(const mrpt::obs::CObservation3DRangeScan& obs, cv::Mat& rgb, cv::Mat& depth,
                core::PinholeCamera& camera);

/// Intrinsics from MRPT's; throws std::invalid_argument for a bad camera (PinholeCamera::Check).
core::PinholeCamera FromMrpt(const mrpt::img::TCamera& camera);
/// A loaded CImage (colour or grey) as CV_8UC3 R G B; throws std::runtime_error if it is empty.
cv::Mat RgbFromImage(const mrpt::img::CImage& image);

Eigen::Isometry3d ToEigen(const mrpt::poses::CPose3D& pose);
mrpt::poses::CPose3D ToMrpt(const Eigen::Isometry3d& pose);
mrpt::img::TCamera ToMrpt(const core::PinholeCamera& camera);

}  // namespace novelty::sensors
