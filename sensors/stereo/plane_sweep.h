// Plane-sweep matching costs (thesis 3.2, [Col96]): fronto-parallel planes of the reference
// (centre) camera at depth hypotheses between a near and a far plane, evenly spaced in inverse
// depth (so evenly in disparity); for each plane, every other camera's image is warped into the
// reference view by the plane's homography and compared pixel by pixel. The cost is the
// truncated absolute colour difference; with several other cameras (trinocular) the smallest of
// their costs is kept, which lets a pixel occluded in one side view be matched in the other.
#pragma once

#include <Eigen/Geometry>
#include <opencv2/core.hpp>
#include <vector>

#include "core/eigen_abi.h"
#include "core/pinhole_camera.h"
#include "sensors/stereo/cost_volume.h"

namespace novelty::sensors {

/// Bounds checked before anything is allocated (a frame's volumes must fit a robot's memory).
inline constexpr int kMaxHypotheses = 512;
inline constexpr double kMaxVolumeBytes = 2.0 * (1 << 30);

struct PlaneSweepOptions {
  double near = 0.5;    ///< nearest depth hypothesis (m)
  double far = 5.0;     ///< farthest depth hypothesis (m)
  int hypotheses = 64;  ///< number of planes (labels)
  /// Truncation of the per-pixel cost: |ΔR|+|ΔG|+|ΔB| is clipped here (0…765 scale), so
  /// occlusions and highlights cost no more than a plain mismatch.
  float truncation = 60.0f;
  /// Side of the box window over which each plane's truncated costs are averaged before belief
  /// propagation (1 = per pixel, as F&H). A small window makes the cost robust to the sensor noise
  /// and to the aperture problem on thin stripes.
  int window = 5;
};

/// Another camera of the rig: its image (same type as the reference, CV_8UC3 or CV_8UC1), its
/// intrinsics and T_ref_other (its pose in the reference camera's frame).
struct SweepView {
  cv::Mat image;
  core::PinholeCamera camera;
  Eigen::Isometry3d ref_from_view = Eigen::Isometry3d::Identity();
};

/// Depth of label l (0 = nearest … hypotheses−1 = farthest); fractional labels interpolate in
/// inverse depth.
double DepthOfLabel(const PlaneSweepOptions& options, double label);

/// The cost volume of `reference` against `others`. Pixels that fall outside every other image
/// for a plane get the truncation cost. Throws std::invalid_argument for images of different
/// sizes or types, no other view, or a bad depth range.
CostVolume PlaneSweep(const cv::Mat& reference, const core::PinholeCamera& camera,
                      const std::vector<SweepView>& others, const PlaneSweepOptions& options);

}  // namespace novelty::sensors
