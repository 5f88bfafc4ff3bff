// Conversions between the project's poses and intrinsics and OpenCV's calib3d conventions
// (rvec, tvec: T_cam_world; K: 3×3 camera matrix).
#pragma once

#include <Eigen/Geometry>
#include <opencv2/calib3d.hpp>
#include <opencv2/core.hpp>
#include <opencv2/core/eigen.hpp>

#include "core/eigen_abi.h"
#include "core/pinhole_camera.h"

namespace novelty::sensors {

inline cv::Mat CameraMatrix(const core::PinholeCamera& c) {
  return (cv::Mat_<double>(3, 3) << c.fx, 0, c.cx, 0, c.fy, c.cy, 0, 0, 1);
}

inline void ToRvecTvec(const Eigen::Isometry3d& world_from_camera, cv::Mat& rvec, cv::Mat& tvec) {
  const Eigen::Isometry3d cam_from_world = world_from_camera.inverse();
  cv::Mat r;
  cv::eigen2cv(Eigen::Matrix3d(cam_from_world.linear()), r);
  cv::Rodrigues(r, rvec);
  cv::eigen2cv(Eigen::Vector3d(cam_from_world.translation()), tvec);
}

inline Eigen::Isometry3d WorldFromRvecTvec(const cv::Mat& rvec, const cv::Mat& tvec) {
  cv::Mat r;
  cv::Rodrigues(rvec, r);
  Eigen::Matrix3d re;
  Eigen::Vector3d te;
  cv::cv2eigen(r, re);
  cv::cv2eigen(tvec, te);
  Eigen::Isometry3d cam_from_world = Eigen::Isometry3d::Identity();
  cam_from_world.linear() = re;
  cam_from_world.translation() = te;
  return cam_from_world.inverse();
}

}  // namespace novelty::sensors
