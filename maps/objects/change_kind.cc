#include "maps/objects/change_kind.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "core/depth_check.h"

namespace novelty::objects {

namespace {
using core::IsKnownDepth;

// Nearer than the farthest surface a view saw there: something now stands in front of it.
bool Nearer(float observed, float farthest, double rel) {
  return observed <= farthest * (1.0 - rel);
}

// The predicted depth's channels per pixel (1, or 2 for a nearest/farthest span); throws unless
// the depths are of the types and the size `what` expects.
int CheckDepths(const cv::Mat& observed_depth, const cv::Mat& predicted_depth, cv::Size size,
                const char* what) {
  const int span = predicted_depth.type() == CV_32FC2 ? 2 : 1;
  if (observed_depth.type() != CV_32FC1 || (predicted_depth.type() != CV_32FC1 && span == 1) ||
      observed_depth.size() != size || predicted_depth.size() != size)
    throw std::invalid_argument(std::string(what) +
                                ": observed depth CV_32F and the predicted depth CV_32F or "
                                "CV_32FC2 (nearest, farthest), of one size");
  return span;
}
}  // namespace

ChangeClassification ClassifyChange(const cv::Mat& region, const cv::Mat& observed_depth,
                                    const cv::Mat& predicted_depth,
                                    const ChangeKindOptions& options) {
  if (region.type() != CV_8UC1)
    throw std::invalid_argument("ClassifyChange: the region must be CV_8U");
  const int span = CheckDepths(observed_depth, predicted_depth, region.size(), "ClassifyChange");
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
      if (!(IsKnownDepth(o[x]) && IsKnownDepth(n) && IsKnownDepth(f))) continue;
      ++known;
      observed += o[x];
      nearest += n;
      farthest += f;
      nearer_pixels += Nearer(o[x], f, rel);
      // Farther than the nearest surface a view saw there: something a view saw has gone.
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

cv::Mat NearerMask(const cv::Mat& observed_depth, const cv::Mat& predicted_depth,
                   const ChangeKindOptions& options) {
  const int span =
      CheckDepths(observed_depth, predicted_depth, observed_depth.size(), "NearerMask");
  cv::Mat mask(observed_depth.size(), CV_8UC1);
  for (int y = 0; y < mask.rows; ++y) {
    const float* o = observed_depth.ptr<float>(y);
    const float* p = predicted_depth.ptr<float>(y);
    uchar* m = mask.ptr<uchar>(y);
    for (int x = 0; x < mask.cols; ++x) {
      const float n = p[span * x], f = p[span * x + span - 1];
      m[x] = IsKnownDepth(o[x]) && IsKnownDepth(n) && IsKnownDepth(f) &&
                     Nearer(o[x], f, options.min_relative_difference)
                 ? 255
                 : 0;
    }
  }
  return mask;
}

}  // namespace novelty::objects
