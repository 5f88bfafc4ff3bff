#include "eval/side_by_side.h"

#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace novelty::eval {

cv::Mat SideBySide(const std::vector<cv::Mat>& images, int gap,
                   const std::vector<std::string>& captions) {
  if (images.empty()) throw std::invalid_argument("SideBySide: no images");
  if (!captions.empty() && captions.size() != images.size())
    throw std::invalid_argument("SideBySide: " + std::to_string(captions.size()) +
                                " captions for " + std::to_string(images.size()) + " images");
  int width = gap * (int(images.size()) - 1);
  for (const cv::Mat& m : images) {
    if (m.type() != CV_8UC3 || m.rows != images[0].rows) {
      throw std::invalid_argument("SideBySide: images must be CV_8UC3 of one height");
    }
    width += m.cols;
  }
  constexpr int kStrip = 16;  // caption strip height: 0.4-scale Hershey text with its descent
  const int top = captions.empty() ? 0 : kStrip;
  cv::Mat out(images[0].rows + top, width, CV_8UC3, cv::Scalar(25, 25, 25));
  int x = 0;
  for (std::size_t k = 0; k < images.size(); ++k) {
    const cv::Mat& m = images[k];
    m.copyTo(out(cv::Rect(x, top, m.cols, m.rows)));
    if (!captions.empty()) {
      cv::putText(out, captions[k], cv::Point(x + 3, kStrip - 4), cv::FONT_HERSHEY_SIMPLEX, 0.4,
                  cv::Scalar(235, 235, 235), 1, cv::LINE_AA);
    }
    x += m.cols + gap;
  }
  return out;
}

}  // namespace novelty::eval
