// View selection (3.3.1): seven representative rays of the virtual camera — three near the image
// centre, four near the corners — and for each ray the reference view of least cost
//   γ = δ / cos φ                                                             (eq. 3.8)
// δ: distance of the reference camera's centre from the ray; φ: angle between the ray and the
// reference camera's optical axis. Views with cos φ ≤ 0 (facing away) are never chosen. The
// result lists each chosen view once.
//
// Eq. 3.8 as printed, ‖r × z‖ / (r·z/‖r‖), contains no reference-camera position, although the
// text defines δ as the distance of the reference camera's centre from the ray; the text is what
// is implemented: δ = ‖(C_j − C_v) × r̂‖.
#pragma once

#include <Eigen/Geometry>
#include <vector>

#include "maps/views/pinhole_camera.h"

namespace novelty::views {

struct ViewSelectionOptions {
  /// The seven points P_i in the virtual image as fractions of width and height.
  std::vector<Eigen::Vector2d> ray_points = {{0.5, 0.5}, {0.35, 0.5}, {0.65, 0.5}, {0.1, 0.1},
                                             {0.9, 0.1}, {0.1, 0.9},  {0.9, 0.9}};
  /// Views farther than this from the virtual camera (metres) are ignored; ≤ 0: no limit.
  double max_distance = 0.0;
};

/// Cost γ of a reference view (pose T_world_ref) for a ray from `centre` along unit `dir`;
/// +infinity if the view faces away.
double ViewCost(const Eigen::Vector3d& centre, const Eigen::Vector3d& dir,
                const Eigen::Isometry3d& T_world_ref);

/// Indices into `reference_poses` of the selected views (each once, in ray order). Empty if no
/// view faces the virtual camera's rays.
std::vector<int> SelectViews(const std::vector<Eigen::Isometry3d>& reference_poses,
                             const PinholeCamera& camera, const Eigen::Isometry3d& T_world_virtual,
                             const ViewSelectionOptions& options = {});

}  // namespace novelty::views
