#include "maps/appearance/room_depth.h"

#include <algorithm>
#include <stdexcept>
#include <utility>
#include <vector>

#include "core/depth_check.h"

namespace novelty::appearance {

namespace {

ViewBasedMapOptions SnapshotOptions(const ViewBasedMapOptions& options) {
  ViewBasedMapOptions o = options;
  o.blend = {};  // nothing is blended: no warp output a blend option asks for is needed
  return o;
}

}  // namespace

RoomDepth::RoomDepth(const ViewBasedMap& map) : map_(SnapshotOptions(map.options())) {
  const views::ReferenceViewStore& store = map.store();
  std::vector<views::ReferenceView> views(std::size_t(store.size()));
  std::vector<views::EncodedView> depths(views.size());
  for (int i = 0; i < store.size(); ++i) {
    views::ReferenceView& v = views[std::size_t(i)];
    if (store.decoded(i)) {
      v = store.Decoded(i);  // shallow
      v.planes.clear();
      continue;
    }
    v.camera = store.camera(i);
    v.T_world_cam = store.pose(i);
    views::EncodedView all = store.Encoded(i);
    depths[std::size_t(i)].encoding = all.encoding;
    depths[std::size_t(i)].planes[""] = std::move(all.planes.at(""));
  }
  map_.Restore(std::move(views), map.anchors(), std::move(depths));
}

cv::Mat RoomDepth::DepthSpan(const core::PinholeCamera& camera,
                             const Eigen::Isometry3d& T_world_cam) {
  return map_.Predict(camera, T_world_cam, {}, /*with_depth=*/true).depth_span;
}

cv::Mat UnionOfDepthSpans(const cv::Mat& a, const cv::Mat& b) {
  if (a.type() != CV_32FC2 || b.type() != CV_32FC2 || a.size() != b.size())
    throw std::invalid_argument("UnionOfDepthSpans: two CV_32FC2 spans of one size expected");
  cv::Mat out(a.size(), CV_32FC2);
  for (int y = 0; y < a.rows; ++y) {
    const cv::Vec2f* pa = a.ptr<cv::Vec2f>(y);
    const cv::Vec2f* pb = b.ptr<cv::Vec2f>(y);
    cv::Vec2f* po = out.ptr<cv::Vec2f>(y);
    for (int x = 0; x < a.cols; ++x) {
      const bool ka = core::IsKnownDepth(pa[x][0]), kb = core::IsKnownDepth(pb[x][0]);
      if (ka && kb) {
        po[x] = {std::min(pa[x][0], pb[x][0]), std::max(pa[x][1], pb[x][1])};
      } else {
        po[x] = ka ? pa[x] : kb ? pb[x] : cv::Vec2f(0.0f, 0.0f);
      }
    }
  }
  return out;
}

}  // namespace novelty::appearance
