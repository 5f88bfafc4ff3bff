#include "sensors/localization/local_normalization.h"

#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace novelty::sensors {

cv::Mat LocallyNormalized(const cv::Mat& grey, const LocalNormalizationOptions& o) {
  CV_Assert(grey.type() == CV_32F);
  if (o.window == 0) return grey;
  if (o.window < 0 || o.window % 2 == 0 || !(o.floor > 0))
    throw std::invalid_argument("local normalization: window must be odd and positive, floor > 0");
  const cv::Size w(o.window, o.window);
  cv::Mat mean, mean_sq;
  cv::boxFilter(grey, mean, CV_32F, w, cv::Point(-1, -1), true, cv::BORDER_REFLECT);
  cv::boxFilter(grey.mul(grey), mean_sq, CV_32F, w, cv::Point(-1, -1), true, cv::BORDER_REFLECT);
  cv::Mat variance = cv::max(mean_sq - mean.mul(mean), 0.0), sigma;
  cv::sqrt(variance, sigma);
  cv::Mat result;
  cv::divide(grey - mean, sigma + o.floor, result, o.scale);
  return result;
}

}  // namespace novelty::sensors
