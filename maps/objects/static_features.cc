#include "maps/objects/static_features.h"

#include <stdexcept>

namespace novelty::objects {

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
  // The active features in the current image (eq. 5.1's p'_g), and eq. 5.2's bound per feature.
  const Eigen::Isometry3d T_cam_world = T_world_cam.inverse();
  std::vector<cv::Point2d> projected;
  std::vector<double> bound;
  std::vector<const ActiveFeature*> visible;
  for (const ActiveFeature& g : active) {
    const Eigen::Vector3d p = T_cam_world * g.p_world;
    if (p.z() <= 0.0) continue;
    const Eigen::Vector2d uv = camera.Project(p);
    projected.emplace_back(uv.x(), uv.y());
    bound.push_back(g.max_descriptor_change);
    visible.push_back(&g);
  }
  std::vector<int> out;
  for (int f = 0; f < int(keypoints.size()); ++f) {
    const cv::Point2d p_f = keypoints[std::size_t(f)].pt;
    for (std::size_t g = 0; g < visible.size(); ++g) {
      if (cv::norm(p_f - projected[g]) >= delta_px) continue;                       // eq. 5.1
      if (cv::norm(descriptors.row(f), visible[g]->descriptor, cv::NORM_L2) > bound[g]) continue;  // eq. 5.2
      out.push_back(f);
      break;
    }
  }
  return out;
}

}  // namespace novelty::objects
