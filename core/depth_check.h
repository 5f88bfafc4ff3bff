// Depth as every part takes it (core/frame.h): float metres, 0 or NaN where unknown. A negative or
// infinite depth is neither: a broken sensor, decoder or file, and would warp pixels behind the
// camera or to infinity. Frames (appearance_map.h CheckFrame) and map files
// (mrpt_plugins/view_archive.cc) refuse them with this count.
#pragma once

#include <opencv2/core.hpp>

#include <cmath>

namespace novelty::core {

/// Whether a depth value is known: positive and finite (0 and NaN are unknown).
inline bool IsKnownDepth(float d) {
  return d > 0.0f && std::isfinite(d);
}

/// The values of `depth` (CV_32FC1) that are negative or ±infinite. Throws std::invalid_argument
/// for another type.
int CountBrokenDepths(const cv::Mat& depth);

}  // namespace novelty::core
