#include "core/false_color.h"

#include <cmath>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace novelty::core {

cv::Mat FalseColor(const cv::Mat& map, double max_value, bool log_scale) {
  if (map.type() != CV_32FC1) throw std::invalid_argument("FalseColor: need a CV_32FC1 map");
  if (!(max_value > 0)) throw std::invalid_argument("FalseColor: max_value must be > 0");
  cv::Mat scaled(map.size(), CV_8UC1);
  const double denom = log_scale ? std::log1p(max_value) : max_value;
  for (int i = 0; i < map.rows * map.cols; ++i) {
    const float v = map.at<float>(i);
    const double x = std::isnan(v) ? 0.0 : (log_scale ? std::log1p(std::max(0.0f, v)) : v) / denom;
    scaled.at<uint8_t>(i) = cv::saturate_cast<uint8_t>(255.0 * x);
  }
  cv::Mat bgr, rgb;
  cv::applyColorMap(scaled, bgr, cv::COLORMAP_INFERNO);
  cv::cvtColor(bgr, rgb, cv::COLOR_BGR2RGB);
  rgb.setTo(cv::Scalar(60, 60, 60), map != map);  // NaN: no data
  return rgb;
}

}  // namespace novelty::core
