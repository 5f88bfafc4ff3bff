#include "mrpt_plugins/cimage_products.h"

#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace novelty::mrpt_plugins {

mrpt::img::CImage ToCImage(const cv::Mat& rgb) {
  if (rgb.empty()) return {};
  if (rgb.type() != CV_8UC3) throw std::invalid_argument("ToCImage: need a CV_8UC3 RGB picture");
  cv::Mat bgr;  // CImage keeps OpenCV's BGR order
  cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
  return mrpt::img::CImage(bgr, mrpt::img::DEEP_COPY);
}

mrpt::obs::CObservationImage::Ptr ProductObservation(const mrpt::img::CImage& image,
                                                     const std::string& label,
                                                     mrpt::Clock::time_point timestamp,
                                                     const mrpt::poses::CPose3D& sensor_pose,
                                                     const mrpt::img::TCamera& camera) {
  auto obs = mrpt::obs::CObservationImage::Create();
  obs->image = image;
  obs->sensorLabel = label;
  obs->timestamp = timestamp;
  obs->cameraPose = sensor_pose;
  obs->cameraParams = camera;
  return obs;
}

}  // namespace novelty::mrpt_plugins
