// Test helper: an arbitrary, general camera pose (turned about two axes, off the origin) for
// round trips of poses through the tracker and the rawlog observations.
#pragma once

#include <Eigen/Geometry>

namespace novelty::sensors {

inline Eigen::Isometry3d SomeCameraPose() {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() = Eigen::AngleAxisd(2.0, Eigen::Vector3d::UnitZ()).toRotationMatrix() *
               Eigen::AngleAxisd(-1.85, Eigen::Vector3d::UnitX()).toRotationMatrix();
  t.translation() = Eigen::Vector3d(0.5, -1.5, 1.1);
  return t;
}

}  // namespace novelty::sensors
