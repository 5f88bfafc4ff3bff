#include "maps/objects/ratio_matches.h"

#include <algorithm>
#include <limits>
#include <opencv2/features2d.hpp>
#include <stdexcept>
#include <string>

namespace novelty::objects {

namespace {

// The k nearest candidates of each reference row; nothing if there are fewer than
// `min_candidates`. `caller` names the function in errors.
std::vector<std::vector<cv::DMatch>> KNearest(const cv::Mat& reference, const cv::Mat& candidates,
                                              int k, int min_candidates, const char* caller) {
  std::vector<std::vector<cv::DMatch>> knn;
  if (reference.empty() || candidates.rows < min_candidates) return knn;
  if (reference.type() != CV_32FC1 || candidates.type() != CV_32FC1 ||
      reference.cols != candidates.cols)
    throw std::invalid_argument(std::string(caller) +
                                ": descriptors must be CV_32F rows of equal width");
  cv::BFMatcher(cv::NORM_L2).knnMatch(reference, candidates, knn, std::min(k, candidates.rows));
  return knn;
}

// The k nearest candidates of each reference row, or nothing if no ratio test can pass.
std::vector<std::vector<cv::DMatch>> Nearest(const cv::Mat& reference, const cv::Mat& candidates,
                                             double ratio, int k) {
  if (!(ratio > 0.0 && ratio <= 1.0))
    throw std::invalid_argument("RatioMatches: ratio must be in (0, 1], got " +
                                std::to_string(ratio));
  return KNearest(reference, candidates, k, 2, "RatioMatches");
}

}  // namespace

std::vector<RatioMatch> RatioMatches(const cv::Mat& reference, const cv::Mat& candidates,
                                     double ratio) {
  std::vector<RatioMatch> out;
  for (const auto& m : Nearest(reference, candidates, ratio, 2)) {
    if (m.size() == 2 && m[0].distance <= ratio * m[1].distance)
      out.push_back({m[0].queryIdx, m[0].trainIdx, m[0].distance});
  }
  return out;
}

std::vector<RatioMatch> RatioMatches(const cv::Mat& reference, const cv::Mat& candidates,
                                     double ratio,
                                     const std::vector<cv::KeyPoint>& candidate_keypoints) {
  if (int(candidate_keypoints.size()) != candidates.rows)
    throw std::invalid_argument("RatioMatches: " + std::to_string(candidate_keypoints.size()) +
                                " keypoints for " + std::to_string(candidates.rows) +
                                " candidates");
  std::vector<RatioMatch> out;
  for (const auto& m : Nearest(reference, candidates, ratio, 16)) {
    if (m.size() < 2) continue;
    const cv::KeyPoint& best = candidate_keypoints[std::size_t(m[0].trainIdx)];
    // None of another place among all candidates: nothing to confuse it with. Among the 16
    // nearest of more: the 16th bounds the distance of the first of another place.
    float second = m.size() < 16 ? std::numeric_limits<float>::infinity() : m.back().distance;
    for (std::size_t i = 1; i < m.size(); ++i) {
      const cv::Point2f d = candidate_keypoints[std::size_t(m[i].trainIdx)].pt - best.pt;
      if (d.dot(d) > 0.25f * best.size * best.size) {
        second = m[i].distance;
        break;
      }
    }
    if (m[0].distance <= ratio * second)
      out.push_back({m[0].queryIdx, m[0].trainIdx, m[0].distance});
  }
  return out;
}

std::vector<RatioMatch> NearestMatches(const cv::Mat& reference, const cv::Mat& candidates, int k) {
  if (k < 1)
    throw std::invalid_argument("NearestMatches: k must be >= 1, got " + std::to_string(k));
  std::vector<RatioMatch> out;
  for (const auto& m : KNearest(reference, candidates, k, 1, "NearestMatches"))
    for (const cv::DMatch& d : m) out.push_back({d.queryIdx, d.trainIdx, d.distance});
  return out;
}

}  // namespace novelty::objects
