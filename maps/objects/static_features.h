// Static features (thesis 5.1, "Identification of static features"): a selected feature f is
// static if some active feature g — one whose 3-D position was reconstructed in an earlier
// frame — reprojects near it and looks like it:
//   ‖p_f − p'_g‖ < δ                                                          (eq. 5.1)
//   ‖d_f − d_g‖ ≤ ‖d_g − d_m‖                                                  (eq. 5.2)
// p'_g: g's 3-D position projected into the current camera; d_m: the descriptor g was matched to
// in the other camera when it was reconstructed. Frames follow each other more closely than the
// rig's cameras are apart, so a static feature's descriptor changes less from frame to frame than
// between the stereo views; a hand moving through the scene fails eq. 5.1.
#pragma once

#include <Eigen/Geometry>
#include <opencv2/core.hpp>
#include <vector>

#include "core/eigen_abi.h"
#include "core/pinhole_camera.h"

namespace novelty::objects {

/// A feature whose 3-D position is known (thesis: an active feature).
struct ActiveFeature {
  Eigen::Vector3d p_world = Eigen::Vector3d::Zero();
  cv::Mat descriptor;  ///< d_g, 1 × n CV_32F
  /// ‖d_g − d_m‖ of eq. 5.2, d_m its match in the other camera when it was reconstructed: how
  /// far its descriptor may move and the feature still count as static.
  double max_descriptor_change = 0.0;
};

/// An active feature in front of the camera, and where it reprojects (p'_g of eq. 5.1, px).
struct ProjectedActiveFeature {
  const ActiveFeature* feature = nullptr;
  Eigen::Vector2d pixel = Eigen::Vector2d::Zero();
};

/// The active features in front of `camera` at T_world_cam, with their reprojections.
std::vector<ProjectedActiveFeature> ProjectActiveFeatures(const std::vector<ActiveFeature>& active,
                                                          const core::PinholeCamera& camera,
                                                          const Eigen::Isometry3d& T_world_cam);

/// Indices of the selected features (keypoints and descriptors, one row each) that are static
/// against `active` seen from `camera` at T_world_cam; δ = `delta_px` (the thesis: 2 px).
/// Throws std::invalid_argument when counts or descriptor widths disagree.
std::vector<int> StaticFeatures(const std::vector<cv::KeyPoint>& keypoints,
                                const cv::Mat& descriptors,
                                const std::vector<ActiveFeature>& active,
                                const core::PinholeCamera& camera,
                                const Eigen::Isometry3d& T_world_cam, double delta_px = 2.0);

}  // namespace novelty::objects
