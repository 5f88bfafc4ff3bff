#include "eval/false_color.h"

#include <cmath>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <string>

namespace novelty::eval {

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

cv::Mat SideBySide(const std::vector<cv::Mat>& images, int gap,
                   const std::vector<std::string>& captions) {
  if (images.empty()) throw std::invalid_argument("SideBySide: no images");
  if (!captions.empty() && captions.size() != images.size())
    throw std::invalid_argument("SideBySide: " + std::to_string(captions.size()) +
                                " captions for " + std::to_string(images.size()) + " images");
  int width = gap * (int(images.size()) - 1);
  for (const cv::Mat& m : images) {
    if (m.type() != CV_8UC3 || m.rows != images[0].rows) {
      throw std::invalid_argument("SideBySide: images must be CV_8UC3 of one height");
    }
    width += m.cols;
  }
  constexpr int kStrip = 16;  // caption strip height: 0.4-scale Hershey text with its descent
  const int top = captions.empty() ? 0 : kStrip;
  cv::Mat out(images[0].rows + top, width, CV_8UC3, cv::Scalar(25, 25, 25));
  int x = 0;
  for (std::size_t k = 0; k < images.size(); ++k) {
    const cv::Mat& m = images[k];
    m.copyTo(out(cv::Rect(x, top, m.cols, m.rows)));
    if (!captions.empty()) {
      cv::putText(out, captions[k], cv::Point(x + 3, kStrip - 4), cv::FONT_HERSHEY_SIMPLEX, 0.4,
                  cv::Scalar(235, 235, 235), 1, cv::LINE_AA);
    }
    x += m.cols + gap;
  }
  return out;
}

}  // namespace novelty::eval
