#include "maps/objects/change_kind.h"

#include <cmath>
#include <stdexcept>

namespace novelty::objects {

ChangeClassification ClassifyChange(const cv::Mat& region, const cv::Mat& observed_depth,
                                    const cv::Mat& predicted_depth,
                                    const ChangeKindOptions& options) {
  if (region.type() != CV_8UC1 || observed_depth.type() != CV_32FC1 ||
      predicted_depth.type() != CV_32FC1 || observed_depth.size() != region.size() ||
      predicted_depth.size() != region.size())
    throw std::invalid_argument("ClassifyChange: region CV_8U and depths CV_32F of one size");
  ChangeClassification c;
  double observed = 0.0, predicted = 0.0;
  long inside = 0, known = 0;
  for (int y = 0; y < region.rows; ++y) {
    const uchar* r = region.ptr<uchar>(y);
    const float* o = observed_depth.ptr<float>(y);
    const float* p = predicted_depth.ptr<float>(y);
    for (int x = 0; x < region.cols; ++x) {
      if (!r[x]) continue;
      ++inside;
      if (!(o[x] > 0.0f && std::isfinite(o[x]) && p[x] > 0.0f && std::isfinite(p[x]))) continue;
      ++known;
      observed += o[x];
      predicted += p[x];
    }
  }
  if (inside == 0) return c;
  c.known_share = double(known) / double(inside);
  if (known == 0) return c;
  c.observed_depth = observed / double(known);
  c.predicted_depth = predicted / double(known);
  if (c.known_share < options.min_known_share) return c;
  const double relative = (c.observed_depth - c.predicted_depth) / c.predicted_depth;
  c.kind = relative <= -options.min_relative_difference  ? ChangeKind::kAdded
           : relative >= options.min_relative_difference ? ChangeKind::kRemoved
                                                         : ChangeKind::kUnchanged;
  return c;
}

}  // namespace novelty::objects
