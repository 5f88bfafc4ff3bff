#include "maps/appearance/foreground_labels.h"

#include <algorithm>
#include <array>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace novelty::appearance {

namespace {

// 8-bit value → linear radiance (the camera's gamma undone).
std::array<float, 256> LinearTable(double gamma) {
  std::array<float, 256> t{};
  for (int v = 0; v < 256; ++v) t[std::size_t(v)] = float(std::pow(v / 255.0, gamma));
  return t;
}

bool IsShadow(const cv::Vec3b& x, const cv::Vec3b& e, const std::array<float, 256>& lin,
              const ForegroundLabelOptions& o) {
  const double luminance = 0.299 * e[0] + 0.587 * e[1] + 0.114 * e[2];
  if (luminance < o.shadow_min_background) return false;
  double lo = 1e30, hi = 0;
  for (int c = 0; c < 3; ++c) {
    const double l = lin[x[c]] / std::max(lin[e[c]], 1e-6f);  // eq. 6.4's illumination image
    lo = std::min(lo, l);
    hi = std::max(hi, l);
  }
  return hi >= o.shadow_min_value && hi <= o.shadow_max_value &&
         (hi - lo) <= o.shadow_max_saturation * hi;
}

void RemoveSmallBlobs(cv::Mat& labels, int min_pixels) {
  cv::Mat components, stats, centroids;
  const int n = cv::connectedComponentsWithStats(labels == kForegroundLabel, components, stats,
                                                 centroids, 8, CV_32S);
  std::vector<bool> small(std::size_t(n), false);
  for (int k = 1; k < n; ++k)
    small[std::size_t(k)] = stats.at<int>(k, cv::CC_STAT_AREA) < min_pixels;
  for (int r = 0; r < labels.rows; ++r)
    for (int c = 0; c < labels.cols; ++c)
      if (small[std::size_t(components.at<int>(r, c))]) labels.at<std::uint8_t>(r, c) = 0;
}

}  // namespace

cv::Mat ForegroundLabels(const cv::Mat& predictive, const cv::Mat& rgb, const cv::Mat& expected_rgb,
                         const ForegroundLabelOptions& o) {
  if (predictive.type() != CV_32FC1 || rgb.type() != CV_8UC3 || expected_rgb.type() != CV_8UC3 ||
      rgb.size() != predictive.size() || expected_rgb.size() != predictive.size())
    throw std::invalid_argument(
        "ForegroundLabels: predictive CV_32FC1, frame and expected image CV_8UC3, one size");
  cv::Mat labels;
  cv::compare(predictive, o.threshold_nats, labels, cv::CMP_GT);  // NaN compares false
  if (o.shadow_label) {
    const std::array<float, 256> lin = LinearTable(o.gamma);
    for (int r = 0; r < labels.rows; ++r) {
      std::uint8_t* l = labels.ptr<std::uint8_t>(r);
      const cv::Vec3b *x = rgb.ptr<cv::Vec3b>(r), *e = expected_rgb.ptr<cv::Vec3b>(r);
      for (int c = 0; c < labels.cols; ++c)
        if (l[c] && IsShadow(x[c], e[c], lin, o)) l[c] = kShadowLabel;
    }
  }
  if (o.min_blob_pixels > 1) RemoveSmallBlobs(labels, o.min_blob_pixels);
  return labels;
}

}  // namespace novelty::appearance
