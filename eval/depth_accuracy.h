// Accuracy of an estimated depth map against ground truth, over the pixels where stereo can
// work at all: textured ones (the local contrast of the reference image is above the sensor
// noise) with a true surface. Used for the sensors issue's "≥ 90 % of textured pixels within 3 %".
#pragma once

#include <opencv2/core.hpp>

namespace novelty::eval {

struct DepthAccuracyOptions {
  /// A pixel is textured when the standard deviation of grey values (0…255) in its window is at
  /// least this — a few times the simulator's / a camera's noise of about 1 grey level.
  double min_texture_std = 4.0;
  int texture_window = 5;        ///< side of that window (pixels, odd)
  double relative_error = 0.03;  ///< |d − d*| / d* counted as correct up to this
  int border = 4;                ///< pixels at the image border are not scored
  /// Pixels within this many pixels of a true depth discontinuity (neighbours differing by more
  /// than `discontinuity_jump`, relative) are scored separately, as Middlebury's "disc" mask:
  /// there any window or smoothness prior must give one side's depth to the other.
  int discontinuity_margin = 2;
  double discontinuity_jump = 0.05;
};

struct DepthAccuracy {
  int scored_pixels = 0;    ///< textured, with true depth, away from discontinuities, estimated
  int textured_pixels = 0;  ///< textured with true depth away from discontinuities
  double within_fraction = 0.0;                ///< share of textured_pixels within relative_error
  double median_relative_error = 0.0;          ///< over scored pixels
  int discontinuity_pixels = 0;                ///< textured pixels near discontinuities
  double discontinuity_within_fraction = 0.0;  ///< their share within relative_error
};

/// `estimate`, `truth`: CV_32F metres (0 or NaN = unknown); `reference`: the image the estimate
/// belongs to (CV_8UC3 RGB or CV_8UC1). A textured pixel without an estimate counts as wrong.
/// The headline numbers exclude pixels near true depth discontinuities, which get their own.
DepthAccuracy MeasureDepthAccuracy(const cv::Mat& estimate, const cv::Mat& truth,
                                   const cv::Mat& reference, const DepthAccuracyOptions& options);

}  // namespace novelty::eval
