#include "eval/object_visibility.h"

#include <map>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace novelty::eval {

int VisiblePixels(const cv::Mat& ids, int id) {
  if (ids.type() != CV_32SC1) throw std::invalid_argument("VisiblePixels: ids must be CV_32SC1");
  int n = 0;
  for (int v = 0; v < ids.rows; ++v)
    for (int u = 0; u < ids.cols; ++u) n += ids.at<int>(v, u) == id;
  return n;
}

NewObjectView NewObjectInView(const cv::Mat& ids, const cv::Mat& novelty, int arm_id,
                              int added_code) {
  if (ids.type() != CV_32SC1 || novelty.type() != CV_8UC1 || ids.size() != novelty.size())
    throw std::invalid_argument("NewObjectInView: ids CV_32SC1 and novelty CV_8UC1 of one size");
  std::map<int, int> pixels;
  NewObjectView view;
  for (int v = 0; v < ids.rows; ++v)
    for (int u = 0; u < ids.cols; ++u) {
      const int id = ids.at<int>(v, u);
      if (id == arm_id)
        ++view.arm_pixels;
      else if (novelty.at<uchar>(v, u) == added_code && id >= 0)
        ++pixels[id];
    }
  for (const auto& [id, n] : pixels)
    if (n > view.pixels) view.id = id, view.pixels = n;
  if (view.id < 0) return view;
  cv::Mat mask = (ids == view.id) & (novelty == added_code);
  view.box = cv::boundingRect(mask);
  return view;
}

}  // namespace novelty::eval
