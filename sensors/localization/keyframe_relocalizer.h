// Re-localization after tracking is lost (thesis 3.1.1; [MMBS09] used SURF): kept keyframes hold
// ORB features of the reference image with their world points (triangulated in the keyframe's
// stereo pair); a new image is matched against every keyframe (ratio test) and its pose found by
// PnP + RANSAC on the keyframe with the most inliers. Shared by the feature-based and the direct
// visual odometry.
#pragma once

#include <Eigen/Geometry>
#include <memory>
#include <opencv2/core.hpp>
#include <optional>

#include "core/eigen_abi.h"
#include "sensors/localization/stereo_pair.h"
#include "sensors/localization/stereo_triangulation.h"

namespace novelty::sensors {

struct KeyframeRelocalizerOptions {
  StereoTriangulationOptions stereo;
  int orb_features = 500;  ///< ORB features detected per image
  double ratio = 0.8;      ///< Lowe's ratio test of the two nearest descriptors
  int ransac_iterations = 200;
  double reprojection_px = 2.0;  ///< RANSAC inlier threshold
  int min_inliers = 12;          ///< fewer: the keyframe does not match
  size_t max_keyframes = 200;    ///< oldest dropped first
};

class KeyframeRelocalizer {
 public:
  explicit KeyframeRelocalizer(const KeyframeRelocalizerOptions& options = {});
  ~KeyframeRelocalizer();
  KeyframeRelocalizer(KeyframeRelocalizer&&) noexcept;
  KeyframeRelocalizer& operator=(KeyframeRelocalizer&&) noexcept;

  /// Keeps `pair` as a keyframe at `world_from_camera` (grey images given to save conversions);
  /// false if too few of its features could be triangulated.
  bool Add(const StereoPair& pair, const cv::Mat& reference_grey, const cv::Mat& other_grey,
           const Eigen::Isometry3d& world_from_camera);
  /// T_world_cam of the reference image `grey` (camera `pair.reference_camera`), or nullopt.
  std::optional<Eigen::Isometry3d> Relocalize(const StereoPair& pair, const cv::Mat& grey) const;
  size_t size() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace novelty::sensors
