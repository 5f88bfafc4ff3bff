// The thesis's descriptor match (5.1): a reference feature matches the candidate whose descriptor
// is nearest (Euclidean), if the second-nearest candidate is farther by a factor: d1 ≤ ratio·d2
// (ratio 0.65 in the thesis). Used against the database, the active features and the other
// camera's features alike. Also the nearest candidates without the test (NearestMatches), the
// putative pairs a geometric verification sorts out: the same search, one filter less.
#pragma once

#include <opencv2/core.hpp>
#include <vector>

namespace novelty::objects {

struct RatioMatch {
  int reference = -1;  ///< row of `reference`
  int candidate = -1;  ///< row of `candidates`
  float distance = 0.0f;
};

/// For each row of `reference` (CV_32F, one descriptor per row), its match among the rows of
/// `candidates` (same type and width), if any. A single candidate cannot pass a ratio test and
/// matches nothing. Throws std::invalid_argument for mismatched descriptors or a ratio outside
/// (0, 1].
std::vector<RatioMatch> RatioMatches(const cv::Mat& reference, const cv::Mat& candidates,
                                     double ratio = 0.65);

/// As above, but the second-nearest is the nearest candidate of another place: one whose
/// keypoint lies farther than the nearest's radius (size / 2) from it. A detector finds one
/// blob at neighbouring scales or orientations, and a textured object repeats a structure a few
/// pixels apart; compared with those, a match the object makes unique fails the ratio test
/// (beyond the thesis, which compared with any second candidate). Among the 16 nearest, the
/// first of another place; if none, the 16th (a lower bound, so the test only gets stricter) —
/// or, with fewer candidates all at one place, none: the match passes.
/// Throws std::invalid_argument also if the keypoints are not one per candidate.
std::vector<RatioMatch> RatioMatches(const cv::Mat& reference, const cv::Mat& candidates,
                                     double ratio,
                                     const std::vector<cv::KeyPoint>& candidate_keypoints);

/// Every row of `reference` with each of its `k` nearest rows of `candidates` (fewer if there
/// are fewer), nearest first, no ratio test: the putative pairs a geometric verification sorts
/// out (object_pose_verification.h). A descriptor seen from another viewpoint or among repeated
/// structure often has its true match nearest but not by the ratio test's margin; a pose that
/// many pairs agree on tells it from chance. Empty `reference` or `candidates`: no pairs.
/// Throws std::invalid_argument for mismatched descriptors or k < 1.
std::vector<RatioMatch> NearestMatches(const cv::Mat& reference, const cv::Mat& candidates, int k);

}  // namespace novelty::objects
