// Direct (photometric) alignment of a keyframe's points with depth to a new image: the pose
// T_cur_kf that minimises Σ ρ(I_cur(π(T·p_i)) − I_kf(u_i)) over the keyframe's points p_i, with
// ρ the Huber loss, by Gauss–Newton (Levenberg–Marquardt damped) on SE(3) from the coarsest
// pyramid level to the finest (as in dense visual odometry, Kerl et al. 2013; Engel et al.
// 2014). Uses every strong gradient (edges too), not only corners — what a scene with few
// textured corners needs.
#pragma once

#include <Eigen/Geometry>
#include <opencv2/core.hpp>
#include <vector>

#include "core/eigen_abi.h"
#include "core/pinhole_camera.h"

namespace novelty::sensors {

struct PhotometricAlignmentOptions {
  int levels = 3;           ///< pyramid levels (each half the size of the previous)
  int max_iterations = 30;  ///< per level
  double huber = 6.0;       ///< Huber threshold of the photometric residual (grey levels)
  /// Image gradient (grey levels per pixel) from which a point of the current image counts as
  /// textured (AlignmentResult::textured_fraction).
  double textured_gradient = 4.0;
  /// Iterations stop when the update's rotation (rad) and translation (m) are below this.
  double convergence = 1e-6;
};

/// An image pyramid (CV_32F grey, 0–255) with its gradients, level 0 the full image. Pixel
/// centres sit at integer coordinates on every level: level l coordinate = level 0 / 2^l.
struct GradientPyramid {
  std::vector<cv::Mat> image, gx, gy;
  static GradientPyramid Build(const cv::Mat& grey, int levels);
};

struct AlignmentResult {
  Eigen::Isometry3d current_from_keyframe = Eigen::Isometry3d::Identity();
  int visible = 0;               ///< points projecting into the current image at level 0
  double rms = 0.0;              ///< RMS photometric residual over all views (grey levels)
  double inlier_fraction = 0.0;  ///< residuals under the Huber threshold, over all views
  /// Residuals where the current image is textured, over all views: near 0 for a blank or
  /// blacked-out image, which otherwise leaves an RMS like that of another lighting.
  double textured_fraction = 0.0;
};

/// One image the keyframe's points are compared with: the current reference image, or another
/// camera of the rig at the same instant (its residuals then constrain the same pose).
struct AlignmentView {
  const GradientPyramid* pyramid = nullptr;
  core::PinholeCamera camera;
  Eigen::Isometry3d view_from_reference = Eigen::Isometry3d::Identity();  ///< the rig offset
};

/// Aligns keyframe points (`points`: keyframe camera frame; `intensity_px`: where each was
/// selected in the keyframe image, whose pyramid is `keyframe` — only its images are read, not
/// its gradients) to `current`, starting from `initial` T_cur_kf.
AlignmentResult AlignPhotometric(const std::vector<Eigen::Vector3d>& points,
                                 const std::vector<cv::Point2f>& intensity_px,
                                 const GradientPyramid& keyframe, const GradientPyramid& current,
                                 const core::PinholeCamera& camera,
                                 const Eigen::Isometry3d& initial,
                                 const PhotometricAlignmentOptions& options = {});

/// The same, with the residuals of every view in `views` (the first is the current reference
/// image, which `visible` counts).
AlignmentResult AlignPhotometric(const std::vector<Eigen::Vector3d>& points,
                                 const std::vector<cv::Point2f>& intensity_px,
                                 const GradientPyramid& keyframe,
                                 const std::vector<AlignmentView>& views,
                                 const Eigen::Isometry3d& initial,
                                 const PhotometricAlignmentOptions& options = {});

}  // namespace novelty::sensors
