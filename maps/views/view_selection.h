// View selection (3.3.1): seven representative rays of the virtual camera — three near the image
// centre, four near the corners — and for each ray the reference view of least cost
//   γ = δ / cos φ                                                             (eq. 3.8)
// δ: distance of the reference camera's centre from the ray; φ: angle between the ray and the
// reference camera's optical axis. Views with cos φ ≤ 0 (facing away) are never chosen. The
// result lists each chosen view once, with the number of rays that chose it: the thesis averages
// seven warped views, one per ray, so a view best for several rays counts that many times.
//
// Eq. 3.8 as printed, ‖r × z‖ / (r·z/‖r‖), contains no reference-camera position, although the
// text defines δ as the distance of the reference camera's centre from the ray; the text is what
// is implemented: δ = ‖(C_j − C_v) × r̂‖.
#pragma once

#include <Eigen/Geometry>
#include <vector>

#include "core/eigen_abi.h"
#include "core/pinhole_camera.h"

namespace novelty::views {

struct ViewSelectionOptions {
  /// The seven points P_i in the virtual image as fractions of width and height.
  std::vector<Eigen::Vector2d> ray_points = {{0.5, 0.5}, {0.35, 0.5}, {0.65, 0.5}, {0.1, 0.1},
                                             {0.9, 0.1}, {0.1, 0.9},  {0.9, 0.9}};
  /// Views farther than this from the virtual camera (metres) are ignored; ≤ 0: no limit.
  double max_distance = 0.0;
  /// true (the thesis's average of one warped view per ray): a view chosen by several rays is
  /// weighted by their number in the blend; false: every selected view once.
  bool weight_by_rays = true;
};

/// The views chosen for the rays.
struct ViewSelection {
  std::vector<int> views;  ///< indices into the reference poses, each once, in ray order
  std::vector<int> rays;   ///< rays[k]: how many rays chose views[k] (≥ 1)
  /// The blend weight of each view under `options` (weight_by_rays: its ray count, else 1).
  std::vector<double> Weights(const ViewSelectionOptions& options) const;
};

/// Cost γ of a reference view (pose T_world_ref) for a ray from `centre` along unit `dir`;
/// +infinity if the view faces away.
double ViewCost(const Eigen::Vector3d& centre, const Eigen::Vector3d& dir,
                const Eigen::Isometry3d& T_world_ref);

/// The best view for each ray, each view once with its ray count. Empty if no view faces the
/// virtual camera's rays.
ViewSelection SelectViewsForRays(const std::vector<Eigen::Isometry3d>& reference_poses,
                                 const core::PinholeCamera& camera,
                                 const Eigen::Isometry3d& T_world_virtual,
                                 const ViewSelectionOptions& options = {});

/// SelectViewsForRays' views alone.
std::vector<int> SelectViews(const std::vector<Eigen::Isometry3d>& reference_poses,
                             const core::PinholeCamera& camera,
                             const Eigen::Isometry3d& T_world_virtual,
                             const ViewSelectionOptions& options = {});

}  // namespace novelty::views
