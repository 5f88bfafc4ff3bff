#include "maps/appearance/differencing_map.h"
#include "maps/views/plane_check.h"

#include <limits>
#include <opencv2/imgproc.hpp>

#include "core/fill_where.h"
#include "maps/color/ycbcr.h"

namespace novelty::appearance {

DifferencingProducts DifferencingMap::Insert(const cv::Mat& rgb, const cv::Mat& depth,
                                             const core::PinholeCamera& camera,
                                             const Eigen::Isometry3d& T_world_cam) {
  CheckFrame(rgb, depth, camera, T_world_cam, "DifferencingMap::Insert");
  const cv::Mat x = color::RgbToYCbCr(rgb);
  Prediction p = map_.Predict(camera, T_world_cam, {{"ycbcr", 3}});
  DifferencingProducts out;
  out.valid = p.valid;
  cv::Mat diff;
  cv::absdiff(x, p.value[0], diff);
  cv::transform(diff, out.difference, cv::Matx13f(1, 1, 1));  // |ΔY| + |ΔCb| + |ΔCr|
  const cv::Mat uncovered = ~p.valid;
  core::FillWhere(out.difference, uncovered, std::numeric_limits<float>::quiet_NaN());
  color::YCbCrToRgb(p.value[0]).convertTo(out.expected_rgb, CV_8UC3);  // NaN → 0 when saturating
  core::FillWhere(out.expected_rgb, uncovered, cv::Scalar::all(0));
  out.update = map_.Update(camera, T_world_cam, depth.clone(), {{"ycbcr", x}}, p.selected);
  return out;
}

void DifferencingMap::CheckStoredPlanes() const {
  views::CheckPlanes(map_.store(), {{"ycbcr", 3, views::PlaneValues::kFiniteOrNaN}});
}

}  // namespace novelty::appearance
