#include "maps/objects/static_features.h"

#include <stdexcept>

namespace novelty::objects {

std::vector<ProjectedActiveFeature> ProjectActiveFeatures(const std::vector<ActiveFeature>& active,
                                                          const core::PinholeCamera& camera,
                                                          const Eigen::Isometry3d& T_world_cam) {
  const Eigen::Isometry3d T_cam_world = T_world_cam.inverse();
  std::vector<ProjectedActiveFeature> visible;
  for (const ActiveFeature& g : active) {
    const Eigen::Vector3d p = T_cam_world * g.p_world;
    if (p.z() > 0.0) visible.push_back({&g, camera.Project(p)});
  }
  return visible;
}

std::vector<int> StaticFeatures(const std::vector<cv::KeyPoint>& keypoints,
                                const cv::Mat& descriptors,
                                const std::vector<ActiveFeature>& active,
                                const core::PinholeCamera& camera,
                                const Eigen::Isometry3d& T_world_cam, double delta_px) {
  if (int(keypoints.size()) != descriptors.rows)
    throw std::invalid_argument("StaticFeatures: " + std::to_string(keypoints.size()) +
                                " keypoints but " + std::to_string(descriptors.rows) +
                                " descriptors");
  for (const ActiveFeature& g : active) {
    if (g.descriptor.cols != descriptors.cols)
      throw std::invalid_argument("StaticFeatures: an active feature's descriptors are " +
                                  std::to_string(g.descriptor.cols) + " wide, not " +
                                  std::to_string(descriptors.cols));
  }
  // The active features in the current image (eq. 5.1's p'_g).
  const std::vector<ProjectedActiveFeature> visible =
      ProjectActiveFeatures(active, camera, T_world_cam);
  std::vector<int> out;
  for (int f = 0; f < int(keypoints.size()); ++f) {
    const Eigen::Vector2d p_f(keypoints[std::size_t(f)].pt.x, keypoints[std::size_t(f)].pt.y);
    for (const ProjectedActiveFeature& g : visible) {
      if ((p_f - g.pixel).norm() >= delta_px) continue;  // eq. 5.1
      if (cv::norm(descriptors.row(f), g.feature->descriptor, cv::NORM_L2) >
          g.feature->max_descriptor_change)
        continue;  // eq. 5.2
      out.push_back(f);
      break;
    }
  }
  return out;
}

}  // namespace novelty::objects
