#include "core/depth_check.h"

#include <cmath>
#include <stdexcept>

namespace novelty::core {

int CountBrokenDepths(const cv::Mat& depth) {
  if (depth.type() != CV_32FC1)
    throw std::invalid_argument("CountBrokenDepths: depth must be CV_32FC1");
  int broken = 0;
  for (int r = 0; r < depth.rows; ++r) {
    const float* d = depth.ptr<float>(r);
    for (int c = 0; c < depth.cols; ++c) broken += d[c] < 0.0f || std::isinf(d[c]);
  }
  return broken;
}

}  // namespace novelty::core
