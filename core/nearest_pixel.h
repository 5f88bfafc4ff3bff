// The pixel a sub-pixel point (a keypoint's centre) is looked up at — its depth, its ground-truth
// id. A detector working on scaled octaves can put a centre past the last pixel's centre, where
// rounding lands one beyond the image; such a point still belongs to the border pixel. One rule,
// so that the learner's and recognition's depth at a keypoint (and the evaluation's id there)
// agree.
#pragma once

#include <algorithm>
#include <cmath>
#include <optional>

#include <opencv2/core.hpp>

namespace novelty::core {

/// The pixel nearest to `p` (rounded half away from zero) in an image of `size`, for a point
/// less than one pixel outside the pixel centres' range (−1 < x < width, likewise y): clamped
/// into the image. Farther out, or not finite: none.
inline std::optional<cv::Point> NearestPixel(const cv::Point2f& p, const cv::Size& size) {
  if (size.empty() ||
      !(p.x > -1.0f && p.y > -1.0f && p.x < float(size.width) && p.y < float(size.height)))
    return std::nullopt;
  return cv::Point(std::clamp(int(std::lround(p.x)), 0, size.width - 1),
                   std::clamp(int(std::lround(p.y)), 0, size.height - 1));
}

}  // namespace novelty::core
