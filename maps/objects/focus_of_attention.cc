#include "maps/objects/focus_of_attention.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace novelty::objects {
namespace {

// The 8-connected part of `binary`'s pixels of 255 (its only other value 0) that holds `seed`,
// CV_8U 255 there, and its bounding box. Both callers' seeds are 255.
cv::Mat ConnectedPart(const cv::Mat& binary, cv::Point seed, cv::Rect& box) {
  cv::Mat mask = cv::Mat::zeros(binary.rows + 2, binary.cols + 2, CV_8U);
  cv::floodFill(binary, mask, seed, cv::Scalar(0), &box, cv::Scalar(0), cv::Scalar(0),
                8 | cv::FLOODFILL_MASK_ONLY | (255 << 8));
  return mask(cv::Rect(1, 1, binary.cols, binary.rows)).clone();
}

}  // namespace

FocusOfAttention FindFocusOfAttention(const cv::Mat& surprise,
                                      const FocusOfAttentionOptions& options) {
  if (surprise.type() != CV_32FC1 || surprise.empty())
    throw std::invalid_argument("FindFocusOfAttention: surprise must be a non-empty CV_32FC1");
  if (!(options.xi >= 0.0 && std::isfinite(options.xi)) || options.morphology_size < 0)
    throw std::invalid_argument("FindFocusOfAttention: xi must be finite and >= 0, "
                                "morphology_size >= 0");
  FocusOfAttention f;
  // Covered: not NaN (cv::compare does not single NaN out reliably in its vector paths).
  cv::Mat covered(surprise.size(), CV_8U);
  f.surprise.create(surprise.size(), CV_32F);
  for (int y = 0; y < surprise.rows; ++y) {
    const float* s = surprise.ptr<float>(y);
    float* out = f.surprise.ptr<float>(y);
    uchar* c = covered.ptr<uchar>(y);
    for (int x = 0; x < surprise.cols; ++x) {
      c[x] = std::isnan(s[x]) ? 0 : 255;
      out[x] = c[x] ? s[x] : 0.0f;
    }
  }
  if (options.morphology_size > 0) {
    const cv::Mat element = cv::getStructuringElement(
        cv::MORPH_RECT, {options.morphology_size, options.morphology_size});
    cv::morphologyEx(f.surprise, f.surprise, cv::MORPH_CLOSE, element);
    cv::morphologyEx(f.surprise, f.surprise, cv::MORPH_OPEN, element);
  }
  f.region = cv::Mat::zeros(surprise.size(), CV_8U);
  if (cv::countNonZero(covered) == 0) return f;
  cv::Scalar mean, stddev;
  cv::meanStdDev(f.surprise, mean, stddev, covered);
  f.threshold = mean[0] + options.xi * stddev[0];
  double max_value = 0.0;
  cv::minMaxLoc(f.surprise, nullptr, &max_value, nullptr, &f.seed, covered);
  // The connected part of {S ≥ θ_S} (covered pixels only) that holds the seed. The seed is at
  // least μ_S, and at least θ_S unless the map is flat (σ_S = 0, where θ_S = μ_S = the maximum).
  cv::Mat above = (f.surprise >= f.threshold) & covered;
  above.at<uchar>(f.seed) = 255;
  f.region = ConnectedPart(above, f.seed, f.box);
  return f;
}

FocusOfAttention MarkSurprising(const FocusOfAttention& focus, const cv::Mat& mask) {
  if (mask.type() != CV_8UC1 || mask.size() != focus.surprise.size())
    throw std::invalid_argument("MarkSurprising: the mask must be CV_8U of the surprise's size");
  // θ_S is a double and the surprise float: raise to the least float not below θ_S, or a marked
  // pixel could fall short of SurprisingShare's test by the rounding.
  float threshold = float(focus.threshold);
  if (double(threshold) < focus.threshold)
    threshold = std::nextafter(threshold, std::numeric_limits<float>::infinity());
  FocusOfAttention marked = focus;
  marked.surprise = focus.surprise.clone();
  cv::Mat raised = cv::max(focus.surprise, threshold);
  raised.copyTo(marked.surprise, mask);
  return marked;
}

FocusOfAttention GrowFocus(const FocusOfAttention& focus, const cv::Mat& mask) {
  if (focus.seed.x < 0) return focus;
  if (mask.type() != CV_8UC1 || mask.size() != focus.region.size())
    throw std::invalid_argument("GrowFocus: the mask must be CV_8U of the focus region's size");
  FocusOfAttention grown = focus;
  grown.region = ConnectedPart(focus.region | (mask != 0), focus.seed, grown.box);
  return grown;
}

double SurprisingShare(const FocusOfAttention& focus, cv::Point2f center, float window,
                       float angle_rad) {
  if (focus.surprise.empty() || !(window > 0.0f)) return 0.0;
  const float co = std::cos(angle_rad), si = std::sin(angle_rad), h = window / 2.0f;
  // One sample per pixel of the window, up to M-SURF's own grid of 24 × 24 samples (24s at
  // step s): the share of a large window is known to ±0.2 % from 576 samples, and a hundred
  // features of 100–250 px windows would otherwise cost milliseconds a frame.
  constexpr int kMaxSamplesPerSide = 24;
  const int n = std::clamp(int(std::lround(window)), 1, kMaxSamplesPerSide);
  int total = 0, above = 0;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const float u = -h + (i + 0.5f) * window / n, v = -h + (j + 0.5f) * window / n;
      const int x = int(std::lround(center.x + u * co - v * si));
      const int y = int(std::lround(center.y + u * si + v * co));
      ++total;
      if (x >= 0 && y >= 0 && x < focus.surprise.cols && y < focus.surprise.rows &&
          focus.surprise.at<float>(y, x) >= focus.threshold)
        ++above;
    }
  }
  return double(above) / total;
}

}  // namespace novelty::objects
