// Test helper: graf1 of the shared data (a real photograph) as a 320×240 R, G, B frame, the size
// of the object map's experiments; empty when the file cannot be read. Shared by the feature
// extractor's test and the object map's benchmark.
#pragma once

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <string>

namespace novelty::objects {

inline cv::Mat GrafFrame(const std::string& graf1_path) {
  const cv::Mat img = cv::imread(graf1_path, cv::IMREAD_COLOR);
  if (img.empty()) return img;
  cv::Mat out;
  cv::resize(img, out, {320, 240}, 0, 0, cv::INTER_AREA);
  cv::cvtColor(out, out, cv::COLOR_BGR2RGB);
  return out;
}

}  // namespace novelty::objects
