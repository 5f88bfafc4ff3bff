#include "maps/objects/ratio_matches.h"

#include <opencv2/features2d.hpp>
#include <stdexcept>
#include <string>

namespace novelty::objects {

std::vector<RatioMatch> RatioMatches(const cv::Mat& reference, const cv::Mat& candidates,
                                     double ratio) {
  if (!(ratio > 0.0 && ratio <= 1.0))
    throw std::invalid_argument("RatioMatches: ratio must be in (0, 1], got " +
                                std::to_string(ratio));
  std::vector<RatioMatch> out;
  if (reference.empty() || candidates.rows < 2) return out;
  if (reference.type() != CV_32FC1 || candidates.type() != CV_32FC1 ||
      reference.cols != candidates.cols)
    throw std::invalid_argument("RatioMatches: descriptors must be CV_32F rows of equal width");
  std::vector<std::vector<cv::DMatch>> knn;
  cv::BFMatcher(cv::NORM_L2).knnMatch(reference, candidates, knn, 2);
  for (const auto& m : knn) {
    if (m.size() == 2 && m[0].distance <= ratio * m[1].distance)
      out.push_back({m[0].queryIdx, m[0].trainIdx, m[0].distance});
  }
  return out;
}

}  // namespace novelty::objects
