#include "maps/views/view_selection.h"

#include <algorithm>
#include <limits>

namespace novelty::views {

double ViewCost(const Eigen::Vector3d& centre, const Eigen::Vector3d& dir,
                const Eigen::Isometry3d& T_world_ref) {
  const Eigen::Vector3d z = T_world_ref.linear().col(2);  // optical axis in world
  const double cos_phi = dir.dot(z);
  if (cos_phi <= 0.0) return std::numeric_limits<double>::infinity();
  const double delta = (T_world_ref.translation() - centre).cross(dir).norm();
  return delta / cos_phi;  // eq. 3.8
}

std::vector<double> ViewSelection::Weights(const ViewSelectionOptions& options) const {
  if (!options.weight_by_rays) return std::vector<double>(views.size(), 1.0);
  return std::vector<double>(rays.begin(), rays.end());
}

ViewSelection SelectViewsForRays(const std::vector<Eigen::Isometry3d>& poses,
                                 const core::PinholeCamera& camera,
                                 const Eigen::Isometry3d& T_world_virtual,
                                 const ViewSelectionOptions& options) {
  const Eigen::Vector3d centre = T_world_virtual.translation();
  ViewSelection selected;
  for (const Eigen::Vector2d& p : options.ray_points) {
    const Eigen::Vector3d dir =
        (T_world_virtual.linear() *
         camera.RayCam(p.x() * (camera.width - 1), p.y() * (camera.height - 1)))
            .normalized();
    int best = -1;
    double best_cost = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < poses.size(); ++j) {
      if (options.max_distance > 0.0 &&
          (poses[j].translation() - centre).norm() > options.max_distance) {
        continue;
      }
      const double cost = ViewCost(centre, dir, poses[j]);
      if (cost < best_cost) {
        best_cost = cost;
        best = static_cast<int>(j);
      }
    }
    if (best < 0) continue;
    const auto at = std::find(selected.views.begin(), selected.views.end(), best);
    if (at == selected.views.end()) {
      selected.views.push_back(best);
      selected.rays.push_back(1);
    } else {
      ++selected.rays[std::size_t(at - selected.views.begin())];
    }
  }
  return selected;
}

std::vector<int> SelectViews(const std::vector<Eigen::Isometry3d>& poses,
                             const core::PinholeCamera& camera,
                             const Eigen::Isometry3d& T_world_virtual,
                             const ViewSelectionOptions& options) {
  return SelectViewsForRays(poses, camera, T_world_virtual, options).views;
}

}  // namespace novelty::views
