#include "maps/views/reference_view_store.h"
#include "core/rigid_pose.h"

#include <stdexcept>

namespace novelty::views {

void ReferenceView::Check(const std::string& what) const {
  camera.Check();
  if (!core::IsRigid(T_world_cam)) {
    throw std::invalid_argument(what + ": pose is not a rigid transform");
  }
  if (depth.type() != CV_32FC1 || depth.rows != camera.height || depth.cols != camera.width) {
    throw std::invalid_argument(
        what + ": depth must be CV_32FC1 of " + std::to_string(camera.width) + "x" +
        std::to_string(camera.height) + ", got " + std::to_string(depth.cols) + "x" +
        std::to_string(depth.rows) + " of type " + std::to_string(depth.type()));
  }
  for (const auto& [name, plane] : planes) {
    if (plane.rows != depth.rows || plane.cols != depth.cols) {
      throw std::invalid_argument(what + ": plane '" + name + "' is " + std::to_string(plane.cols) +
                                  "x" + std::to_string(plane.rows) + ", depth is " +
                                  std::to_string(depth.cols) + "x" + std::to_string(depth.rows));
    }
  }
}

ReferenceView ReferenceViewOf(const core::Frame& frame, const std::string& plane) {
  if (!frame.T_world_cam) {
    throw std::invalid_argument("frame " + std::to_string(frame.index) +
                                ": no pose, cannot become a reference view");
  }
  ReferenceView v;
  v.camera = frame.camera;
  v.T_world_cam = *frame.T_world_cam;
  v.depth = frame.depth;
  v.planes[plane] = frame.rgb;
  return v;
}

std::size_t ReferenceView::BytesUsed() const {
  std::size_t bytes = depth.total() * depth.elemSize();
  for (const auto& [name, plane] : planes) bytes += plane.total() * plane.elemSize();
  return bytes;
}

int ReferenceViewStore::Add(ReferenceView view) {
  view.Check("reference view " + std::to_string(views_.size()));
  views_.push_back(std::move(view));
  return size() - 1;
}

void ReferenceViewStore::Replace(int i, ReferenceView view) {
  if (i < 0 || i >= size()) {
    throw std::out_of_range("ReferenceViewStore::Replace: no view " + std::to_string(i));
  }
  view.Check("reference view " + std::to_string(i));
  views_[static_cast<std::size_t>(i)] = std::move(view);
}

std::vector<Eigen::Isometry3d> ReferenceViewStore::Poses() const {
  std::vector<Eigen::Isometry3d> poses;
  poses.reserve(views_.size());
  for (const ReferenceView& v : views_) poses.push_back(v.T_world_cam);
  return poses;
}

std::size_t ReferenceViewStore::BytesUsed() const {
  std::size_t bytes = 0;
  for (const ReferenceView& v : views_) bytes += v.BytesUsed();
  return bytes;
}

}  // namespace novelty::views
