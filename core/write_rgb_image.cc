#include "core/write_rgb_image.h"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace novelty::core {

void WriteImage(const std::string& path, const cv::Mat& image, const std::vector<int>& params) {
  if (!cv::imwrite(path, image, params)) throw std::runtime_error(path + ": cannot write image");
}

void WriteRgbImage(const std::string& path, const cv::Mat& rgb, const std::vector<int>& params) {
  cv::Mat bgr;
  cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
  WriteImage(path, bgr, params);
}

}  // namespace novelty::core
