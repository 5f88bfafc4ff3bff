#include "sensors/localization/epipolar_feature_matching.h"

#include <limits>
#include <stdexcept>
#include <string>

namespace novelty::sensors {

std::vector<EpipolarFeatureMatch> MatchAlongEpipolarLines(
    const StereoPair& pair, const std::vector<cv::KeyPoint>& reference_keypoints,
    const cv::Mat& reference_descriptors, const std::vector<cv::KeyPoint>& other_keypoints,
    const cv::Mat& other_descriptors, const StereoTriangulationOptions& triangulation,
    double ratio) {
  if (int(reference_keypoints.size()) != reference_descriptors.rows ||
      int(other_keypoints.size()) != other_descriptors.rows)
    throw std::invalid_argument("MatchAlongEpipolarLines: keypoint and descriptor counts differ");
  if (!reference_descriptors.empty() && !other_descriptors.empty() &&
      (reference_descriptors.type() != CV_32FC1 || other_descriptors.type() != CV_32FC1 ||
       reference_descriptors.cols != other_descriptors.cols))
    throw std::invalid_argument("MatchAlongEpipolarLines: descriptors must be CV_32F rows of "
                                "equal width");
  if (!(ratio > 0.0 && ratio <= 1.0))
    throw std::invalid_argument("MatchAlongEpipolarLines: ratio must be in (0, 1], got " +
                                std::to_string(ratio));
  std::vector<EpipolarFeatureMatch> out;
  constexpr double kInf = std::numeric_limits<double>::infinity();
  for (int i = 0; i < reference_descriptors.rows; ++i) {
    double best = kInf, second = kInf, second_overall = kInf, best_overall = kInf;
    EpipolarFeatureMatch m;
    for (int j = 0; j < other_descriptors.rows; ++j) {
      const double d = cv::norm(reference_descriptors.row(i), other_descriptors.row(j), cv::NORM_L2);
      if (d < best_overall) {
        second_overall = best_overall, best_overall = d;
      } else if (d < second_overall) {
        second_overall = d;
      }
      if (d >= second) continue;  // cannot become the best two on the line
      const auto p = Triangulate(pair, reference_keypoints[std::size_t(i)].pt,
                                 other_keypoints[std::size_t(j)].pt, triangulation);
      if (!p) continue;
      if (d < best) {
        second = best, best = d;
        m = {i, j, *p, float(d)};
      } else {
        second = d;
      }
    }
    if (m.other < 0) continue;
    // The second-nearest on the line, or of all when the line holds one candidate; the best of
    // all is then the match itself or nearer, and the runner-up of all is what it must beat.
    const double reference = second < kInf ? second
                             : best_overall < best ? best_overall
                                                   : second_overall;
    if (best <= ratio * reference) out.push_back(m);
  }
  return out;
}

}  // namespace novelty::sensors
