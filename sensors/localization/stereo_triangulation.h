// Stereo features: KLT matching of reference-image points into the other image of the rig (with
// sub-pixel accuracy, as [MSSB09]) and their triangulation in the reference camera's frame.
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <optional>
#include <vector>

#include "core/eigen_abi.h"
#include "sensors/localization/stereo_pair.h"

namespace novelty::sensors {

struct StereoTriangulationOptions {
  double min_depth = 0.3;  ///< m; nearer (or behind) is a mismatch
  double max_depth = 8.0;  ///< m; farther is too uncertain to localize with
  /// A match whose rays miss each other by more than this, in pixels of the other image, is
  /// rejected (the epipolar constraint).
  double max_epipolar_error = 1.0;
  int klt_window = 21;  ///< KLT window side (pixels)
  int klt_levels = 4;   ///< KLT pyramid levels (0-based max level)
};

/// Camera-frame point from a correspondence by the midpoint of the two rays' closest approach;
/// nullopt when the epipolar error or the depth is out of bounds.
std::optional<Eigen::Vector3d> Triangulate(const StereoPair& pair, const cv::Point2f& ref_px,
                                           const cv::Point2f& other_px,
                                           const StereoTriangulationOptions& options);

/// Matches `points` (reference image) into the other image by KLT and triangulates them; one
/// entry per point. Grey images are passed to save the conversion.
std::vector<std::optional<Eigen::Vector3d>> TriangulateFeatures(
    const StereoPair& pair, const cv::Mat& reference_grey, const cv::Mat& other_grey,
    const std::vector<cv::Point2f>& points, const StereoTriangulationOptions& options);

}  // namespace novelty::sensors
