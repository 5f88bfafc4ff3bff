#include "eval/psnr.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace novelty::eval {

double Psnr(const cv::Mat& a, const cv::Mat& b, const cv::Mat& mask, double peak) {
  if (a.size() != b.size() || a.channels() != b.channels()) {
    throw std::invalid_argument("Psnr: images differ in size or channel count");
  }
  if (!mask.empty() && (mask.size() != a.size() || mask.type() != CV_8UC1)) {
    throw std::invalid_argument("Psnr: mask must be CV_8UC1 of the images' size");
  }
  cv::Mat fa, fb;
  a.convertTo(fa, CV_64F);
  b.convertTo(fb, CV_64F);
  const int n = mask.empty() ? a.rows * a.cols : cv::countNonZero(mask);
  if (n == 0) return std::numeric_limits<double>::quiet_NaN();
  const double sse = std::pow(cv::norm(fa, fb, cv::NORM_L2, mask), 2.0);
  const double mse = sse / (double(n) * a.channels());
  if (mse == 0.0) return std::numeric_limits<double>::infinity();
  return 10.0 * std::log10(peak * peak / mse);
}

}  // namespace novelty::eval
