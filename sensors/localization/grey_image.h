// The grey image the localization steps work on: an RGB image converted, a grey one as it is.
#pragma once

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

namespace novelty::sensors {

inline cv::Mat GreyImage(const cv::Mat& image) {
  if (image.channels() == 1) return image;
  cv::Mat grey;
  cv::cvtColor(image, grey, cv::COLOR_RGB2GRAY);
  return grey;
}

}  // namespace novelty::sensors
