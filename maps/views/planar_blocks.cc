#include "maps/views/planar_blocks.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace novelty::views {
namespace {

bool IsPlanar(const cv::Mat& depth, int u0, int v0, int size, float tolerance) {
  const float z00 = depth.at<float>(v0, u0), z10 = depth.at<float>(v0, u0 + size);
  const float z01 = depth.at<float>(v0 + size, u0);
  if (!(z00 > 0.0f && z10 > 0.0f && z01 > 0.0f)) return false;
  // ŵ(u, v) = w00 + du·(u − u0) + dv·(v − v0)
  const float w00 = 1.0f / z00;
  const float du = (1.0f / z10 - w00) / float(size), dv = (1.0f / z01 - w00) / float(size);
  for (int y = 0; y <= size; ++y) {
    const float* z = depth.ptr<float>(v0 + y) + u0;
    const float row = w00 + dv * float(y);
    for (int x = 0; x <= size; ++x) {
      // Written so that NaN, infinite or non-positive depths fail.
      if (!(z[x] > 0.0f && std::abs(z[x] * (row + du * float(x)) - 1.0f) <= tolerance))
        return false;
    }
  }
  return true;
}

}  // namespace

cv::Mat FindPlanarBlocks(const cv::Mat& depth, int size, double tolerance) {
  if (depth.type() != CV_32FC1)
    throw std::invalid_argument("FindPlanarBlocks: depth must be CV_32FC1");
  if (size < 1)
    throw std::invalid_argument("FindPlanarBlocks: block size must be at least 1, got " +
                                std::to_string(size));
  const int bx = std::max(0, (depth.cols - 1) / size), by = std::max(0, (depth.rows - 1) / size);
  cv::Mat flags(by, bx, CV_8UC1, cv::Scalar(0));
  for (int y = 0; y < by; ++y)
    for (int x = 0; x < bx; ++x)
      if (IsPlanar(depth, x * size, y * size, size, float(tolerance))) flags.at<uchar>(y, x) = 255;
  return flags;
}

}  // namespace novelty::views
