#include "core/float_image.h"

#include <opencv2/core.hpp>
#include <stdexcept>
#include <string>

namespace novelty::core {

cv::Mat ToFloat255(const cv::Mat& image) {
  const int depth = image.depth();
  if (depth != CV_8U && depth != CV_16U && depth != CV_32F)
    throw std::invalid_argument("ToFloat255: 8-bit, 16-bit or float images only, got depth " +
                                std::to_string(depth));
  cv::Mat f;
  image.convertTo(f, CV_MAKETYPE(CV_32F, image.channels()),
                  depth == CV_16U ? 255.0 / 65535.0 : 1.0);
  return f;
}

cv::Mat ChannelMean(const cv::Mat& image) {
  const cv::Mat f = ToFloat255(image);
  if (f.channels() == 1) return f;
  cv::Mat mean;
  cv::transform(f, mean, cv::Mat(1, f.channels(), CV_32F, cv::Scalar(1.0 / f.channels())));
  return mean;
}

}  // namespace novelty::core
