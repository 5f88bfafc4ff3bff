// Reference views of an image-based map (thesis ch. 3): per view the intrinsics, the pose
// T_world_cam, a depth map and any number of named per-pixel planes (an image, normal-gamma
// parameter planes, an illumination-invariant image, …). Geometry (camera, pose, depth) and data
// (planes) stay apart, so one warp serves every plane.
//
// Memory: depth is kept as CV_32F; planes keep the type they are given (CV_8U, CV_16F, CV_32F,
// any channel count), so a map stores what it needs at the precision it needs.
// BytesUsed() reports the total.
#pragma once

#include <Eigen/Geometry>
#include <map>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "core/eigen_abi.h"
#include "core/frame.h"
#include "core/pinhole_camera.h"

namespace novelty::views {

struct ReferenceView {
  core::PinholeCamera camera;
  Eigen::Isometry3d T_world_cam = Eigen::Isometry3d::Identity();
  cv::Mat depth;                          ///< CV_32F metres along +Z; 0 or NaN = unknown
  std::map<std::string, cv::Mat> planes;  ///< same size as depth, any type

  /// Throws std::invalid_argument naming `what` and the problem: a pose that is not a rigid
  /// transform, a depth map of the wrong size or type, a plane of the wrong size.
  void Check(const std::string& what) const;
  std::size_t BytesUsed() const;
};

/// A frame with a pose as a reference view holding its image as plane `plane`. Throws
/// std::invalid_argument naming the frame if it has no pose.
ReferenceView ReferenceViewOf(const core::Frame& frame, const std::string& plane = "rgb");

class ReferenceViewStore {
 public:
  /// Adds a view (checked) and returns its index.
  int Add(ReferenceView view);
  /// Replaces view i (checked); the update policy of 4.3 replaces views in place.
  void Replace(int i, ReferenceView view);

  const ReferenceView& view(int i) const { return views_.at(static_cast<std::size_t>(i)); }
  ReferenceView& mutable_view(int i) { return views_.at(static_cast<std::size_t>(i)); }
  int size() const { return static_cast<int>(views_.size()); }
  std::vector<Eigen::Isometry3d> Poses() const;
  std::size_t BytesUsed() const;

 private:
  std::vector<ReferenceView> views_;
};

}  // namespace novelty::views
