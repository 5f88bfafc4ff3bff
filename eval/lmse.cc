#include "eval/lmse.h"

#include <algorithm>
#include <stdexcept>
#include <vector>

namespace novelty::eval {

namespace {

cv::Mat AsDouble(const cv::Mat& m) {
  cv::Mat d;
  m.convertTo(d, CV_64F);
  return d;
}

}  // namespace

double LocalMse(const cv::Mat& correct, const cv::Mat& estimate, const cv::Mat& mask, int window) {
  if (correct.empty() || correct.channels() != 1 || estimate.channels() != 1 ||
      estimate.size() != correct.size() || mask.type() != CV_8UC1 ||
      mask.size() != correct.size() || window < 1)
    throw std::invalid_argument(
        "LocalMse: one-channel truth and estimate of one size, a CV_8UC1 mask of that size and "
        "window >= 1 are needed");
  const cv::Mat t = AsDouble(correct), e = AsDouble(estimate);
  const int shift = std::max(1, window / 2);
  double ssq = 0.0, total = 0.0;
  for (int y = 0; y + window <= t.rows; y += shift) {
    for (int x = 0; x + window <= t.cols; x += shift) {
      double te = 0.0, ee = 0.0, tt = 0.0;
      for (int v = y; v < y + window; ++v) {
        const double* tr = t.ptr<double>(v);
        const double* er = e.ptr<double>(v);
        const uchar* mr = mask.ptr<uchar>(v);
        for (int u = x; u < x + window; ++u) {
          if (!mr[u]) continue;
          te += tr[u] * er[u];
          ee += er[u] * er[u];
          tt += tr[u] * tr[u];
        }
      }
      // Σ (t - a e)² with the least-squares a = Σte / Σee (0 for a vanishing estimate, as the
      // reference code's 1e-5 guard).
      const double a = ee > 1e-5 ? te / ee : 0.0;
      ssq += std::max(0.0, tt - 2.0 * a * te + a * a * ee);
      total += tt;
    }
  }
  if (!(total > 0.0))
    throw std::invalid_argument(
        "LocalMse: no window holds a scored pixel with a non-zero truth (empty mask, or a "
        "window larger than the image)");
  return ssq / total;
}

IntrinsicScore ScoreIntrinsic(const cv::Mat& true_shading, const cv::Mat& true_reflectance,
                              const cv::Mat& shading, const cv::Mat& reflectance,
                              const cv::Mat& mask, int window) {
  const int channels = reflectance.channels();
  if ((channels != 1 && channels != 3) ||
      (true_reflectance.channels() != 1 && true_reflectance.channels() != channels))
    throw std::invalid_argument(
        "ScoreIntrinsic: reflectances need 1 or 3 channels, the truth 1 or as many as the "
        "estimate");
  IntrinsicScore s;
  s.shading = LocalMse(true_shading, shading, mask, window);
  std::vector<cv::Mat> est, truth;
  cv::split(reflectance, est);
  cv::split(true_reflectance, truth);
  for (int c = 0; c < channels; ++c)
    s.reflectance += LocalMse(truth[truth.size() == 1 ? 0 : c], est[c], mask, window);
  s.reflectance /= channels;
  s.lmse = 0.5 * s.shading + 0.5 * s.reflectance;
  return s;
}

}  // namespace novelty::eval
