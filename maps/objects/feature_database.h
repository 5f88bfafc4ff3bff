// The feature database of the surprise-driven object learner (thesis 5.1, "Recognition /
// learning of new object features"): one set of features DF for all known objects, and per
// feature h and object k the count n_{h,k} of its detections on k. A feature belongs to the
// object of highest relative frequency
//   p_{h,k} = n_{h,k} / Σ_k n_{h,k}                                           (eq. 5.3)
// Recognition counts, per object, the database features that a selected feature matches
// (ratio_matches.h, 0.65) — N_k for the most probable object of each matched feature — and
// names the object of most matches
//   c = argmax_k N_k                                                           (eq. 5.4)
// and each match adds 1 to n_{h,M} of its feature's most probable object M. New features enter
// with n = 1 for the object they were learnt on and 0 for the others (eq. 5.6, 5.7). As written,
// a feature's counts grow on its most probable object only, so p_{h,k} stays 1 for the object it
// was learnt on; it would differ if one descriptor were learnt on two objects.
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <string>
#include <utility>
#include <vector>

#include "core/eigen_abi.h"
#include "maps/objects/keypoint_consistency.h"
#include "maps/objects/ratio_matches.h"

namespace novelty::objects {

/// What the database knows of an object besides its features (beyond the thesis, whose objects
/// are numbers): a name, and for an object learnt from a photo the outline of its pixels in the
/// photo's plane — its features then lie in that plane (z = 0, metres), and a recognition is
/// verified by a homography (planar_object_verification.h) that maps the outline into the image.
struct ObjectInfo {
  std::string name;                      ///< empty: unnamed (DisplayName gives "object k")
  std::vector<Eigen::Vector2d> outline;  ///< empty: learnt in the world, features at 3-D places
  bool planar() const { return !outline.empty(); }
};

class FeatureDatabase {
 public:
  struct Recognition {
    std::vector<int> matches_per_object;  ///< N_k, one per known object
    int object = -1;                      ///< c of eq. 5.4; −1 if every N_k is 0
    std::vector<RatioMatch> matches;      ///< reference = database feature h, candidate = selected
  };

  int objects() const { return objects_; }
  int features() const { return descriptors_.rows; }
  const cv::Mat& descriptors() const { return descriptors_; }

  /// A new object class v (eq. 5.5 decided that one is needed); returns its index. Throws
  /// std::invalid_argument for a name with a control character or longer than kMaxNameLength,
  /// or an outline of fewer than 3 or more than kMaxOutline points or with a non-finite one.
  int AddObject(ObjectInfo info = {});
  static constexpr std::size_t kMaxNameLength = 200, kMaxOutline = 64;
  /// Why AddObject would refuse `info` (a name with a control character or too long, an outline
  /// that is no polygon); empty if it would not.
  static std::string InfoError(const ObjectInfo& info);
  const ObjectInfo& Info(int k) const;
  /// The name, or "object k" for an unnamed object.
  std::string DisplayName(int k) const;
  /// Adds the rows of `descriptors` (CV_32F, the database's width) as features learnt on
  /// `object` (eq. 5.6, 5.7), with their 3-D positions (world frame, where the object stood when
  /// they were learnt; NaN or none given: unknown) and their keypoints' orientation and metric
  /// size (keypoint_consistency.h; none given: unknown). Throws std::invalid_argument for an
  /// unknown object, bad rows, a position or keypoint count that is not the row count, or a
  /// keypoint angle outside [0, 360) or size that is not positive (NaN is unknown).
  void AddFeatures(const cv::Mat& descriptors, int object,
                   const std::vector<Eigen::Vector3d>& positions = {},
                   const std::vector<LearntKeypoint>& keypoints = {});

  /// Matches the selected features' descriptors against the database and updates the counts
  /// (eq. 5.4 and the n_{h,M} increments). `ratio`: the thesis's 0.65.
  /// With `keypoints` (one per selected row), the ratio test's second candidate is one of another
  /// place (ratio_matches.h).
  Recognition Recognize(const cv::Mat& selected, double ratio = 0.65,
                        const std::vector<cv::KeyPoint>* keypoints = nullptr);
  /// The same matches and N_k without updating the counts: recognition by a robot that no
  /// longer learns (the thesis's I3).
  Recognition Match(const cv::Mat& selected, double ratio = 0.65,
                    const std::vector<cv::KeyPoint>* keypoints = nullptr) const;
  /// N_k and c of eq. 5.4 for given matches (reference = database feature): what Match counts,
  /// for a subset of its matches. Throws std::out_of_range for a reference not in the database.
  Recognition Tally(std::vector<RatioMatch> matches) const;

  /// n_{h,k}.
  int Count(int h, int k) const;
  /// p_{h,k} of eq. 5.3.
  double RelativeFrequency(int h, int k) const;
  /// The object of highest p_{h,k} (the lowest index among equals).
  int MostProbableObject(int h) const;
  /// Feature h's position (world frame where it was learnt); NaN if unknown.
  const Eigen::Vector3d& Position(int h) const;
  /// Feature h's keypoint when it was learnt (NaN members: unknown).
  const LearntKeypoint& Keypoint(int h) const;

  /// Per feature its non-zero counts (object, n_{h,k}), for saving.
  using Counts = std::vector<std::vector<std::pair<int, int>>>;
  const Counts& counts() const { return n_; }
  /// A database from what a saved one held (`keypoints` empty: all unknown, as in files written
  /// before they were kept; `info` empty: every object unnamed). Throws std::invalid_argument
  /// naming what is inconsistent (widths, counts per feature, objects out of range, counts < 1, a
  /// keypoint or info count that is not the feature or object count, keypoints as AddFeatures
  /// refuses, info as AddObject refuses).
  static FeatureDatabase FromParts(int objects, const cv::Mat& descriptors, const Counts& counts,
                                   const std::vector<Eigen::Vector3d>& positions,
                                   const std::vector<LearntKeypoint>& keypoints = {},
                                   const std::vector<ObjectInfo>& info = {});

 private:
  void CheckFeature(int h) const;

  cv::Mat descriptors_;                     // DF, one row per feature
  Counts n_;                                // per feature: (object, n_{h,k} > 0)
  std::vector<Eigen::Vector3d> positions_;  // per feature, NaN unknown
  std::vector<LearntKeypoint> keypoints_;   // per feature, NaN unknown
  std::vector<ObjectInfo> info_;            // per object
  int objects_ = 0;
};

}  // namespace novelty::objects
