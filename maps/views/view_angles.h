// The view angle per warped pixel, for view-dependent blending weights (view_blender.h).
#pragma once

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "core/eigen_abi.h"
#include "core/pinhole_camera.h"

namespace novelty::views {

// Per covered virtual pixel: cos of the angle between the rays from the surface point to the
// virtual camera centre (origin) and to the source camera centre (in virtual coordinates), into
// `cos_angle` (reused frame to frame: fresh images cost page faults). In float with one square
// root per pixel, in a loop the compiler vectorises.
void ViewAngles(const cv::Mat& depth, const core::PinholeCamera& cam, const Eigen::Vector3d& source,
                cv::Mat& cos_angle);

}  // namespace novelty::views
