// The baseline of 4.3.2: an image-based map of raw YCbCr images with the same view selection,
// warping and replacement policy as the appearance map; a frame is scored per pixel by
// |ΔY| + |ΔCb| + |ΔCr| against the image predicted at its viewpoint.
#pragma once

#include <opencv2/core.hpp>

#include "maps/appearance/appearance_map.h"
#include "maps/appearance/view_based_map.h"

namespace novelty::appearance {

struct DifferencingProducts {
  cv::Mat difference;    ///< CV_32FC1 |ΔY|+|ΔCb|+|ΔCr|, NaN where not covered
  cv::Mat expected_rgb;  ///< CV_8UC3 predicted image
  cv::Mat valid;
  ViewBasedMap::UpdateResult update;
};

class DifferencingMap {
 public:
  explicit DifferencingMap(const ViewBasedMapOptions& options = {})
      : options_(options), map_(options) {}
  /// Same inputs and errors as AppearanceMap::Insert.
  DifferencingProducts Insert(const cv::Mat& rgb, const cv::Mat& depth,
                              const core::PinholeCamera& camera,
                              const Eigen::Isometry3d& T_world_cam);
  const views::ReferenceViewStore& store() const { return map_.store(); }
  /// Throws std::invalid_argument naming the view unless every view holds a Y, Cb, Cr plane of
  /// finite values (NaN: unknown) (for maps read from files).
  void CheckStoredPlanes() const;
  const ViewBasedMapOptions& options() const { return options_; }
  /// The reference images and their anchors, for saving and loading a map.
  const ViewBasedMap& view_map() const { return map_; }
  ViewBasedMap& view_map() { return map_; }

 private:
  ViewBasedMapOptions options_;
  ViewBasedMap map_;
};

}  // namespace novelty::appearance
