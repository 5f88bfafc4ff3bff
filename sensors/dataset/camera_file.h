// Camera intrinsics from a calibration file, read by MRPT (mrpt::img::TCamera): a ROS
// camera_info / camera_calibration_parsers YAML (image_width, image_height, camera_matrix,
// distortion_coefficients; .yaml or .yml) or an MRPT camera .ini ([CAMERA_PARAMS] resolution,
// cx, cy, fx, fy, dist). The maps take undistorted images: a calibration with non-zero distortion
// is refused (rectify the images first, e.g. with the ROS image_proc or OpenCV's undistort).
#pragma once

#include <string>

#include "core/pinhole_camera.h"

namespace novelty::sensors {

/// Throws std::runtime_error naming `path`: unreadable, missing fields, implausible values
/// (sizes, focal lengths), or distortion.
core::PinholeCamera ReadCameraFile(const std::string& path);

}  // namespace novelty::sensors
