// Local mean squared error of an intrinsic-image decomposition, the score of the MIT Intrinsic
// Images benchmark (Grosse, Johnson, Adelson, Freeman, ICCV 2009, eq. 9 and its reference code):
// windows of k × k pixels shifted by k/2; in each the estimate is scaled by the factor that fits
// it to the truth in least squares (an intrinsic image is known only up to scale), the squared
// errors over the mask are summed, and the sum over all windows is divided by the sum of the
// truth's squares over the same windows, so that an all-zero estimate scores 1. The benchmark's
// score is 0.5 · LMSE(shading) + 0.5 · LMSE(reflectance).
#pragma once

#include <opencv2/core.hpp>

namespace novelty::eval {

/// `correct`, `estimate`: one-channel images (any depth) of one size; `mask`: CV_8UC1 of that
/// size, non-zero where scored. `window` ≥ 1 (the benchmark: 20), shifted by max(1, window/2).
/// Windows that do not fit the image are not scored (as the reference code). Throws
/// std::invalid_argument for mismatched inputs, and when no window holds a scored pixel whose
/// truth is non-zero (the reference code's score would be NaN).
double LocalMse(const cv::Mat& correct, const cv::Mat& estimate, const cv::Mat& mask,
                int window = 20);

struct IntrinsicScore {
  double shading = 0.0;      ///< LMSE of the shading estimate
  double reflectance = 0.0;  ///< LMSE of the reflectance estimate (mean over its channels)
  double lmse = 0.0;         ///< 0.5 · shading + 0.5 · reflectance (the benchmark's score)
};

/// Scores a decomposition. The shadings are one-channel; the reflectances have one channel or
/// three (then each channel is scored with its own scale, as the reference code allows, and the
/// three are averaged; a one-channel truth is compared with each).
IntrinsicScore ScoreIntrinsic(const cv::Mat& true_shading, const cv::Mat& true_reflectance,
                              const cv::Mat& shading, const cv::Mat& reflectance,
                              const cv::Mat& mask, int window = 20);

}  // namespace novelty::eval
