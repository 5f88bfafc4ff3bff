#include "maps/objects/box_filters.h"

#include <opencv2/imgproc.hpp>

namespace novelty::objects {

cv::Mat UnitIntegral(cv::InputArray image) {
  const cv::Mat m = image.getMat();
  CV_Assert(!m.empty() && (m.depth() == CV_8U || m.depth() == CV_32F || m.depth() == CV_64F) &&
            (m.channels() == 1 || m.channels() == 3));
  cv::Mat grey = m;
  if (m.channels() == 3) cv::cvtColor(m, grey, cv::COLOR_BGR2GRAY);
  cv::Mat unit, integral;
  grey.convertTo(unit, CV_64F, grey.depth() == CV_8U ? 1.0 / 255.0 : 1.0);
  cv::integral(unit, integral, CV_64F);
  return integral;
}

}  // namespace novelty::objects
