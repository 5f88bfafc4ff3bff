// Local contrast normalization for photometric alignment: (I − μ_w) / (σ_w + floor) · scale,
// with μ_w, σ_w the mean and standard deviation over a window around each pixel. An image
// under changed lighting (a lamp moved: a smooth, spatially varying gain and offset) normalizes
// to nearly the same image, so direct alignment survives the change; `floor` keeps flat,
// noisy regions from being blown up to full contrast.
#pragma once

#include <opencv2/core.hpp>

namespace novelty::sensors {

struct LocalNormalizationOptions {
  int window = 9;       ///< side of the square window (pixels, odd); 0 = no normalization
  double floor = 10.0;  ///< added to σ (grey levels)
  /// Output units per σ: with the default, a pixel one σ off its neighbourhood's mean of a
  /// well-textured region reads about ±40, the range of grey levels the alignment thresholds
  /// (Huber, RMS) are set for.
  double scale = 50.0;
};

/// `grey`: CV_32F. Returns CV_32F of the same size (`grey` itself when window is 0).
cv::Mat LocallyNormalized(const cv::Mat& grey, const LocalNormalizationOptions& options = {});

}  // namespace novelty::sensors
