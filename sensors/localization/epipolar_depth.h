// Depth of selected reference-image pixels from a calibrated stereo pair by a one-dimensional
// search along each pixel's epipolar line in the other image (the semi-dense stereo of direct
// visual odometry): sum of squared differences of a small patch at one-pixel steps between the
// projections of the near and the far depth, a uniqueness test against the second-best
// non-adjacent position, a parabola through the best three for sub-pixel accuracy, the same
// search back from the match (left–right consistency), then triangulation. Pixels are chosen where the image gradient along the epipolar direction is
// strong, since only there does the search have a well-defined minimum.
#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "sensors/localization/stereo_pair.h"
#include "sensors/localization/stereo_triangulation.h"

namespace novelty::sensors {

struct EpipolarDepthOptions {
  StereoTriangulationOptions range;  ///< min/max depth and epipolar tolerance of triangulation
  int patch_radius = 2;              ///< SSD patch (2 → 5×5 pixels)
  /// Best SSD must be below this fraction of the second best more than 2 px away.
  double uniqueness = 0.6;
  /// Largest mean squared difference per patch pixel (grey levels²) of an accepted match.
  double max_mean_ssd = 150.0;
  /// The match searched back into the reference image must land this close (pixels) to where
  /// it started (left–right consistency); 0 = no check.
  double max_left_right_px = 1.0;
  int block = 4;  ///< at most one pixel per block × block cell is selected
  /// Selected pixels need this gradient (grey levels per pixel) along the epipolar direction.
  double min_epipolar_gradient = 6.0;
};

struct EpipolarPoint {
  cv::Point2f px;      ///< reference pixel
  float depth;         ///< along the reference camera's +Z (metres)
};

/// Selects pixels of `reference` (CV_32F grey, 0–255) with strong gradient along the epipolar
/// direction, one per block, and returns those whose depth could be measured in `other`.
std::vector<EpipolarPoint> EpipolarDepths(const StereoPair& pair, const cv::Mat& reference,
                                          const cv::Mat& other,
                                          const EpipolarDepthOptions& options = {});

}  // namespace novelty::sensors
