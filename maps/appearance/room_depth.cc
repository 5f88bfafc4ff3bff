#include "maps/appearance/room_depth.h"

#include <utility>
#include <vector>

namespace novelty::appearance {

namespace {

ViewBasedMapOptions SnapshotOptions(const ViewBasedMapOptions& options) {
  ViewBasedMapOptions o = options;
  o.storage.decoded_views = 0;  // depth alone: re-encoding on every eviction would cost more
  return o;
}

}  // namespace

RoomDepth::RoomDepth(const ViewBasedMap& map) : map_(SnapshotOptions(map.options())) {
  std::vector<views::ReferenceView> views;
  for (int i = 0; i < map.store().size(); ++i) {
    views::ReferenceView v = map.store().Decoded(i);
    v.planes.clear();
    views.push_back(std::move(v));
  }
  map_.Restore(std::move(views), map.anchors());
}

cv::Mat RoomDepth::DepthSpan(const core::PinholeCamera& camera,
                             const Eigen::Isometry3d& T_world_cam) {
  return map_.Predict(camera, T_world_cam, {}, /*with_depth=*/true).depth_span;
}

}  // namespace novelty::appearance
