#include "sensors/rawlog/rgbd_observation.h"

#include <cmath>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace novelty::sensors {

namespace {

constexpr float kRangeUnits = kRgbdRangeUnits;

// Columns: the 3D-scan axes (+X forward, +Y left, +Z up) in camera coordinates.
Eigen::Isometry3d CameraFromSensor() {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.linear() << 0, -1, 0, 0, 0, -1, 1, 0, 0;
  return t;
}

}  // namespace

Eigen::Isometry3d ToEigen(const mrpt::poses::CPose3D& pose) {
  const auto m = pose.getHomogeneousMatrixVal<mrpt::math::CMatrixDouble44>();
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) t.matrix()(r, c) = m(r, c);
  return t;
}

mrpt::poses::CPose3D ToMrpt(const Eigen::Isometry3d& p) {
  mrpt::math::CMatrixDouble44 m;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) m(r, c) = p.matrix()(r, c);
  return mrpt::poses::CPose3D(m);
}

mrpt::img::TCamera ToMrpt(const core::PinholeCamera& camera) {
  mrpt::img::TCamera k;
  k.ncols = uint32_t(camera.width);
  k.nrows = uint32_t(camera.height);
  k.fx(camera.fx);
  k.fy(camera.fy);
  k.cx(camera.cx);
  k.cy(camera.cy);
  return k;
}

mrpt::obs::CObservation3DRangeScan MakeRgbdObservation(double time, const cv::Mat& rgb,
                                                       const cv::Mat& depth,
                                                       const core::PinholeCamera& camera,
                                                       const Eigen::Isometry3d& robot_from_camera) {
  mrpt::obs::CObservation3DRangeScan obs;
  obs.timestamp = mrpt::Clock::fromDouble(time);
  obs.sensorLabel = "RGBD";
  obs.cameraParams = obs.cameraParamsIntensity = ToMrpt(camera);
  obs.sensorPose = ToMrpt(robot_from_camera * CameraFromSensor());
  obs.range_is_depth = true;
  obs.rangeUnits = kRangeUnits;
  obs.hasRangeImage = true;
  obs.rangeImage_setSize(depth.rows, depth.cols);
  for (int r = 0; r < depth.rows; ++r) {
    for (int c = 0; c < depth.cols; ++c) {
      const float d = depth.at<float>(r, c);
      obs.rangeImage(r, c) = (d > 0 && std::isfinite(d))
                                 ? uint16_t(std::min(65535.0f, std::round(d / kRangeUnits)))
                                 : 0;
    }
  }
  obs.hasIntensityImage = true;
  cv::Mat bgr;
  cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
  obs.intensityImage = mrpt::img::CImage(bgr, mrpt::img::DEEP_COPY);
  return obs;
}

Eigen::Isometry3d CameraOnRobot(const mrpt::obs::CObservation3DRangeScan& obs) {
  return ToEigen(obs.sensorPose) * CameraFromSensor().inverse();
}

void DecodeRgbd(const mrpt::obs::CObservation3DRangeScan& obs, cv::Mat& rgb, cv::Mat& depth,
                core::PinholeCamera& camera) {
  if (!obs.hasRangeImage || !obs.hasIntensityImage) {
    throw std::runtime_error("no range or no intensity image");
  }
  const auto& range = obs.rangeImage;
  rgb = RgbFromImage(obs.intensityImage);
  if (rgb.rows != int(range.rows()) || rgb.cols != int(range.cols())) {
    throw std::runtime_error("intensity image not the range image's size");
  }
  depth.create(rgb.rows, rgb.cols, CV_32FC1);
  for (int r = 0; r < rgb.rows; ++r) {
    for (int c = 0; c < rgb.cols; ++c) depth.at<float>(r, c) = float(range(r, c)) * obs.rangeUnits;
  }
  camera = FromMrpt(obs.cameraParamsIntensity);
}

core::PinholeCamera FromMrpt(const mrpt::img::TCamera& k) {
  core::PinholeCamera camera;
  camera.width = int(k.ncols);
  camera.height = int(k.nrows);
  camera.fx = k.fx();
  camera.fy = k.fy();
  camera.cx = k.cx();
  camera.cy = k.cy();
  camera.Check();
  return camera;
}

cv::Mat RgbFromImage(const mrpt::img::CImage& image) {
  const cv::Mat bgr = image.asCvMat<cv::Mat>(mrpt::img::SHALLOW_COPY);
  if (bgr.empty()) throw std::runtime_error("image missing or unreadable");
  cv::Mat rgb;
  if (bgr.type() == CV_8UC3)
    cv::cvtColor(bgr, rgb, cv::COLOR_BGR2RGB);
  else if (bgr.type() == CV_8UC1)
    cv::cvtColor(bgr, rgb, cv::COLOR_GRAY2RGB);
  else
    throw std::runtime_error("image is neither 8-bit colour nor grey");
  return rgb;
}

}  // namespace novelty::sensors
