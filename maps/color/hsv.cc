#include "maps/color/hsv.h"

#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <string>

namespace novelty::color {

cv::Mat RgbToHsv(const cv::Mat& rgb) {
  if (rgb.type() != CV_8UC3 && rgb.type() != CV_32FC3) {
    throw std::invalid_argument(
        "RgbToHsv: expected an RGB image of type CV_8UC3 or CV_32FC3, "
        "got OpenCV type " +
        std::to_string(rgb.type()));
  }
  // The float path keeps full precision (the 8-bit path quantises H to 0…179).
  cv::Mat rgb_f;
  rgb.convertTo(rgb_f, CV_32F);
  cv::Mat hsv;
  cv::cvtColor(rgb_f, hsv, cv::COLOR_RGB2HSV);
  return hsv;
}

}  // namespace novelty::color
