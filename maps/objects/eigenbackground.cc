#include "maps/objects/eigenbackground.h"

#include <cmath>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <string>

namespace novelty::objects {

cv::Mat EigenbackgroundForeground(const std::vector<cv::Mat>& backgrounds, const cv::Mat& image,
                                  const EigenbackgroundOptions& options) {
  const int n = int(backgrounds.size());
  if (n < 2)
    throw std::invalid_argument("Eigenbackground: needs at least 2 background images, got " +
                                std::to_string(n));
  if (options.components < 1 || !(options.threshold > 0.0) || options.morphology_size < 0)
    throw std::invalid_argument(
        "Eigenbackground: components >= 1, threshold > 0, morphology_size >= 0");
  if (image.type() != CV_32FC1)
    throw std::invalid_argument("Eigenbackground: the image must be CV_32FC1");
  for (const cv::Mat& b : backgrounds)
    if (b.type() != CV_32FC1 || b.size() != image.size())
      throw std::invalid_argument(
          "Eigenbackground: backgrounds must be CV_32FC1 of the image's size");
  // Pixels every background covers.
  cv::Mat covered(image.size(), CV_8UC1, cv::Scalar(255));
  for (const cv::Mat& b : backgrounds) covered &= (b == b);  // NaN != NaN
  covered &= (image == image);
  const int p = cv::countNonZero(covered);
  cv::Mat foreground = cv::Mat::zeros(image.size(), CV_8UC1);
  if (p == 0) return foreground;
  // One row per background image over the covered pixels, then PCA (mean + eigenvectors).
  cv::Mat data(n, p, CV_32F), x(1, p, CV_32F);
  for (int i = 0; i < n; ++i) {
    int c = 0;
    for (int v = 0; v < image.rows; ++v)
      for (int u = 0; u < image.cols; ++u)
        if (covered.at<uchar>(v, u))
          data.at<float>(i, c++) = backgrounds[std::size_t(i)].at<float>(v, u);
  }
  {
    int c = 0;
    for (int v = 0; v < image.rows; ++v)
      for (int u = 0; u < image.cols; ++u)
        if (covered.at<uchar>(v, u)) x.at<float>(0, c++) = image.at<float>(v, u);
  }
  const cv::PCA pca(data, cv::noArray(), cv::PCA::DATA_AS_ROW, std::min(options.components, n - 1));
  const cv::Mat back = pca.backProject(pca.project(x));  // the background the image would show
  int c = 0;
  for (int v = 0; v < image.rows; ++v)
    for (int u = 0; u < image.cols; ++u)
      if (covered.at<uchar>(v, u)) {
        if (std::abs(x.at<float>(0, c) - back.at<float>(0, c)) > options.threshold)
          foreground.at<uchar>(v, u) = 255;
        ++c;
      }
  if (options.morphology_size > 0) {
    const cv::Mat k = cv::getStructuringElement(
        cv::MORPH_RECT, cv::Size(options.morphology_size, options.morphology_size));
    cv::morphologyEx(foreground, foreground, cv::MORPH_OPEN, k);
    cv::morphologyEx(foreground, foreground, cv::MORPH_CLOSE, k);
  }
  return foreground;
}

cv::Mat LargestRegion(const cv::Mat& mask) {
  if (mask.type() != CV_8UC1) throw std::invalid_argument("LargestRegion: mask must be CV_8UC1");
  cv::Mat labels, stats, centroids;
  const int count = cv::connectedComponentsWithStats(mask, labels, stats, centroids, 8, CV_32S);
  int best = 0, area = 0;
  for (int i = 1; i < count; ++i)
    if (stats.at<int>(i, cv::CC_STAT_AREA) > area)
      best = i, area = stats.at<int>(i, cv::CC_STAT_AREA);
  cv::Mat out = cv::Mat::zeros(mask.size(), CV_8UC1);
  if (best > 0) out.setTo(255, labels == best);
  return out;
}

}  // namespace novelty::objects
