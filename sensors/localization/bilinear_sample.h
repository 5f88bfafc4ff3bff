// Bilinear sample of a CV_32F image at (x, y); the caller keeps 0 ≤ x < cols − 1 and
// 0 ≤ y < rows − 1. Pixel centres are at integer coordinates.
#pragma once

#include <opencv2/core.hpp>

namespace novelty::sensors {

inline float SampleBilinear(const cv::Mat& m, float x, float y) {
  const int x0 = int(x), y0 = int(y);
  const float ax = x - float(x0), ay = y - float(y0);
  const float* r0 = m.ptr<float>(y0);
  const float* r1 = m.ptr<float>(y0 + 1);
  return (1 - ay) * ((1 - ax) * r0[x0] + ax * r0[x0 + 1]) +
         ay * ((1 - ax) * r1[x0] + ax * r1[x0 + 1]);
}

}  // namespace novelty::sensors
