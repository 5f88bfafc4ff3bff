#include "maps/objects/change_kind.h"

#include <cmath>
#include <stdexcept>

namespace novelty::objects {

namespace {
bool Known(float d) {
  return d > 0.0f && std::isfinite(d);
}
}  // namespace

ChangeClassification ClassifyChange(const cv::Mat& region, const cv::Mat& observed_depth,
                                    const cv::Mat& predicted_depth,
                                    const ChangeKindOptions& options) {
  const int span = predicted_depth.type() == CV_32FC2 ? 2 : 1;
  if (region.type() != CV_8UC1 || observed_depth.type() != CV_32FC1 ||
      (predicted_depth.type() != CV_32FC1 && span == 1) || observed_depth.size() != region.size() ||
      predicted_depth.size() != region.size())
    throw std::invalid_argument(
        "ClassifyChange: region CV_8U, observed depth CV_32F and the "
        "predicted depth CV_32F or CV_32FC2 (nearest, farthest), of one "
        "size");
  ChangeClassification c;
  double observed = 0.0, nearest = 0.0, farthest = 0.0;
  long inside = 0, known = 0, nearer_pixels = 0, farther_pixels = 0;
  const double rel = options.min_relative_difference;
  for (int y = 0; y < region.rows; ++y) {
    const uchar* r = region.ptr<uchar>(y);
    const float* o = observed_depth.ptr<float>(y);
    const float* p = predicted_depth.ptr<float>(y);
    for (int x = 0; x < region.cols; ++x) {
      if (!r[x]) continue;
      ++inside;
      const float n = p[span * x], f = p[span * x + span - 1];
      if (!(Known(o[x]) && Known(n) && Known(f))) continue;
      ++known;
      observed += o[x];
      nearest += n;
      farthest += f;
      // Nearer than the farthest surface a view saw there: something now stands in front of
      // it. Farther than the nearest: something a view saw there has gone.
      nearer_pixels += o[x] <= f * (1.0 - rel);
      farther_pixels += o[x] >= n * (1.0 + rel);
    }
  }
  if (inside == 0) return c;
  c.known_share = double(known) / double(inside);
  if (known == 0) return c;
  c.observed_depth = observed / double(known);
  nearest /= double(known);
  farthest /= double(known);
  c.predicted_depth = farthest;
  c.nearer_share = double(nearer_pixels) / double(known);
  c.farther_share = double(farther_pixels) / double(known);
  if (c.known_share < options.min_known_share) return c;
  // Pixel by pixel, not by the means: one object swapped for another where it stood leaves most
  // of the region at the depth it had, and only the part of the new one that sticks out nearer.
  if (c.nearer_share >= options.min_changed_share && c.nearer_share >= c.farther_share) {
    c.kind = ChangeKind::kAdded;
  } else if (c.farther_share >= options.min_changed_share) {
    c.kind = ChangeKind::kRemoved;
    c.predicted_depth = nearest;
  } else {
    c.kind = ChangeKind::kUnchanged;
  }
  return c;
}

}  // namespace novelty::objects
