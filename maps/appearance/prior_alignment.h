// Aligning a frame to the map's prior by a small camera rotation, before the update.
//
// A pose source's error moves the whole prior against the frame. The LED tracker's is mostly
// rotation (0.16°, about 0.8 px at 320×240; its 0.34 mm of translation move a point 1 m away by
// 0.15 px) and is smoothed over 0.4 s, so the frames of one pass agree with each other and a later
// pass lands every edge about a pixel away from what the map learnt (warp_error_floor.h). A
// rotation moves every pixel independently of depth, by the homography K·R·K⁻¹, so it can be
// estimated from the frame and the prior alone: Gauss-Newton on the luminance, robust (Huber) to
// what is new in the frame, with a gain and a bias (a view seen once holds a τ between the initial
// prior and the colour; exposure). The map then predicts again at the corrected pose
// (AppearanceMapOptions::align_to_prior).
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "core/eigen_abi.h"
#include "core/pinhole_camera.h"

namespace novelty::appearance {

struct PriorAlignmentOptions {
  int max_iterations = 20;     ///< Gauss-Newton steps at most
  double blur_sigma_px = 1.0;  ///< both images are smoothed first: a basin wider than a pixel
  double huber_levels = 10.0;  ///< residual (Y levels) beyond which a pixel's weight falls as 1/|r|
  double max_rotation_rad = 0.01;  ///< a larger correction (0.57°) is refused: not a small error
  double min_gradient = 2.0;       ///< Y levels per pixel from which a pixel counts as textured
  int min_pixels = 400;            ///< fewer covered, textured pixels: no alignment
  /// A step that moves no pixel farther than this ends the iterations (at an edge of 100 levels
  /// per pixel a hundredth of a pixel is one level, the sensor's noise); max_iterations without
  /// one refuses the alignment.
  double converged_px = 0.01;
};

struct PriorAlignment {
  /// False: too few pixels textured in both, a failed solve, no convergence or too large a
  /// rotation; rotation is then 0 (pixels and iterations say how far it got).
  bool aligned = false;
  /// ω (rad, camera frame, +X right, +Y down, +Z forward): the frame's camera is the given one
  /// rotated by exp([ω]×), i.e. T_world_cam_true = T_world_cam · R(ω).
  Eigen::Vector3d rotation = Eigen::Vector3d::Zero();
  int pixels = 0;  ///< covered pixels textured in prior and frame, in the last step
  int iterations = 0;
};

/// The rotation under which `prior_y` (CV_32FC1, the prior's τ_Y at the given pose, NaN where
/// not covered) best explains `observed_y` (CV_32FC1, the frame's Y): a·prior_y(K·R(ω)·K⁻¹·x) + b
/// ≈ observed_y(x), with a gain a > 0 and a bias b. Throws std::invalid_argument for planes that do
/// not match the camera or bad options.
PriorAlignment AlignRotationToPrior(const cv::Mat& observed_y, const cv::Mat& prior_y,
                                    const core::PinholeCamera& camera,
                                    const PriorAlignmentOptions& options = {});

/// R(ω) = exp([ω]×).
Eigen::Matrix3d RotationFromVector(const Eigen::Vector3d& omega);

}  // namespace novelty::appearance
