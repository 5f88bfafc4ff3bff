// Pinhole intrinsics (eq. 3.7 without skew) and the camera pose, in the project's conventions:
// camera +Z forward, +X right, +Y down; pose T_world_cam maps camera coordinates to world
// coordinates.
#pragma once

#include <Eigen/Geometry>

#include "core/eigen_abi.h"

namespace novelty::core {

struct PinholeCamera {
  int width = 320;
  int height = 240;
  double fx = 400.0, fy = 400.0;  ///< focal lengths in pixels
  double cx = 159.5, cy = 119.5;  ///< principal point; pixel centres are at integer coordinates

  /// A camera with the given horizontal field of view and a centred principal point.
  static PinholeCamera FromFov(int width, int height, double horizontal_fov_rad);

  /// Direction in camera coordinates through pixel (u, v), with z = 1 (so ray parameter = depth).
  Eigen::Vector3d RayCam(double u, double v) const;
  /// Pixel coordinates of a camera-frame point (z > 0).
  Eigen::Vector2d Project(const Eigen::Vector3d& p_cam) const;
  /// Back-projects pixel (u, v) with depth d (along +Z) into camera coordinates (eq. 3.6, 3.9).
  Eigen::Vector3d Unproject(double u, double v, double depth) const { return depth * RayCam(u, v); }
  /// Throws std::invalid_argument if sizes are not positive or a focal length is zero or not
  /// finite. A negative focal length is allowed (e.g. ICL-NUIM's fy < 0: image y axis up).
  void Check() const;
};

}  // namespace novelty::core
