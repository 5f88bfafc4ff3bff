// The depth of the room as a view-based map's views held it at one moment — the room the robot
// knew before it looked for objects (thesis ch. 5 compares with "the expected appearance … as it
// has been captured in I1") — predicted at any viewpoint.
//
// Why a snapshot: the map goes on learning, and its update policy (view_based_map.h) replaces a
// view's depth with each frame's. Once the robot has passed a new object, the views around it
// hold the object's depth, and a test against them ("does this stand nearer than the room?") no
// longer finds it added. The snapshot keeps the views' depths and poses of the moment it was
// taken and predicts their depth span as the map would have.
#pragma once

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "core/eigen_abi.h"
#include "core/pinhole_camera.h"
#include "maps/appearance/view_based_map.h"

namespace novelty::appearance {

class RoomDepth {
 public:
  /// The depths, cameras and poses of `map`'s views now, with its view selection, warp and
  /// storage options; the payload planes are not kept. Depths the map holds decoded are shared
  /// (the map replaces a view's depth, it never writes into it); compact ones are copied encoded,
  /// so the snapshot takes what the map's depths take, and decodes a view's depth alone when a
  /// prediction selects it.
  explicit RoomDepth(const ViewBasedMap& map);

  /// CV_32FC2, per pixel the nearest and the farthest depth over the snapshot's views selected
  /// for this viewpoint that cover it, as Prediction::depth_span: (0, 0) where none covers (and
  /// everywhere if the snapshot holds no view), NaN where the covering view had no depth.
  cv::Mat DepthSpan(const core::PinholeCamera& camera, const Eigen::Isometry3d& T_world_cam);

  int views() const { return map_.store().size(); }

 private:
  ViewBasedMap map_;
};

/// Per pixel, the nearest and the farthest depth of two spans together (CV_32FC2 each, of one
/// size): the nearest of the two nearest, the farthest of the two farthest, over the known ones
/// (0 and NaN are unknown; unknown in both gives (0, 0)). Throws std::invalid_argument if the
/// types or sizes differ.
cv::Mat UnionOfDepthSpans(const cv::Mat& a, const cv::Mat& b);

}  // namespace novelty::appearance
