// Recognition of learnt objects in a whole frame, by a robot that no longer learns (thesis 5.2,
// sequence I3): features are extracted from the frame (no surprise map: the room is new), each
// database feature is matched with the ratio test (eq. 5.4's matching) and counts for its most
// probable object (eq. 5.3). Per object the number of matches N_k is the thesis's score (its
// ROC sweeps the number of matches required); beyond the thesis, the matches of an object can be
// verified geometrically (object_pose_verification.h): the score is then the number of matches
// that agree on one pose of the object, counted at distinct places — or, with verify_nearest,
// of the features' nearest keypoints without the ratio test.
#pragma once

#include <opencv2/features2d.hpp>
#include <vector>

#include "core/eigen_abi.h"
#include "core/pinhole_camera.h"
#include "maps/objects/feature_database.h"
#include "maps/objects/keypoint_consistency.h"
#include "maps/objects/object_pose_verification.h"

namespace novelty::objects {

struct ObjectEvidence {
  int matches = 0;    ///< N_k: matched database features whose most probable object is k
  VerifiedPose pose;  ///< set when verification was asked for and k has matches (or pairs)
};

struct FrameRecognition {
  std::vector<cv::KeyPoint> keypoints;     ///< the frame's features
  std::vector<RatioMatch> matches;         ///< reference = database feature, candidate = keypoint
  std::vector<ObjectEvidence> per_object;  ///< one per database object
};

/// Of `matches[i]` for i in `agreeing`, those that are separate pieces of evidence: each
/// database feature once, and a keypoint only if farther than 2·tolerance_px from every one
/// counted before — nearer, both could be the image of one point. A detector finds one blob at
/// neighbouring scales and orientations, a feature may have several candidates there, and a pose
/// that puts the whole object far away collapses it onto one cluster of keypoints.
int DistinctPlaces(const std::vector<RatioMatch>& matches, const std::vector<int>& agreeing,
                   const std::vector<cv::KeyPoint>& keypoints, double tolerance_px);

/// The matches of `object` among `matches` as 2-D–3-D pairs (the database features' learnt
/// places and the keypoints' pixels), verified by VerifyObjectPose. When verified, `inliers`
/// counts the agreeing pairs that are separate evidence: each database feature once, and
/// keypoints more than 2·reprojection_px apart (nearer, two could be the image of one projected
/// point); the object is verified only if that count reaches min_inliers. `inlier_pairs` index
/// `matches`. An object learnt from a photo (ObjectInfo::planar) is verified by a homography
/// instead (planar_object_verification.h), and its pose then comes from the homography's inliers.
VerifiedPose VerifyObjectMatches(const FeatureDatabase& database,
                                 const std::vector<RatioMatch>& matches,
                                 const std::vector<cv::KeyPoint>& keypoints, int object,
                                 const core::PinholeCamera& camera,
                                 const PoseVerificationOptions& options);

struct ObjectRecognitionOptions {
  double match_ratio = 0.65;  ///< the ratio test's bound (thesis 5.1: 0.65)
  /// The ratio test's second candidate of another place (ratio_matches.h); false: the thesis's.
  bool distinct_second = false;
  bool verify = false;  ///< verify each object with matches (object_pose_verification.h)
  /// With verify: the pairs verified are each database feature's this many nearest keypoints,
  /// without the ratio test (ratio_matches.h, NearestMatches), and every object is verified;
  /// 0: the ratio matches, and only objects that have some (eq. 5.4's matches verified).
  int verify_nearest = 0;
  PoseVerificationOptions verification;
  /// Count only matches whose keypoint agrees with the learnt one's orientation and metric size
  /// (keypoint_consistency.h); with verify_nearest = 0 they are also the pairs verified. Not
  /// enabled: the thesis.
  KeypointConsistencyOptions consistency;
};

struct FrameFeatures {
  std::vector<cv::KeyPoint> keypoints;
  cv::Mat descriptors;  ///< CV_32F, one row per keypoint
  /// Per keypoint its size in metres (MetricSizes; NaN unknown), or empty: all unknown.
  std::vector<double> metric_sizes;
};

/// The features of a whole frame, `grey` CV_8UC1.
FrameFeatures ExtractFrameFeatures(const cv::Mat& grey, cv::Feature2D& extractor);
/// The same with their metric sizes, from `depth` (CV_32FC1 metres of `grey`'s size; empty:
/// unknown) seen by `camera`. Throws std::invalid_argument for a depth of another size, or
/// (MetricSizes) of another type.
FrameFeatures ExtractFrameFeatures(const cv::Mat& grey, cv::Feature2D& extractor,
                                   const cv::Mat& depth, const core::PinholeCamera& camera);

/// Of `matches` (reference = database feature, candidate = a keypoint of `features`), those
/// whose keypoint agrees with the feature's learnt one (keypoint_consistency.h), with N_k and c
/// counted over them as FeatureDatabase::Match counts (Tally). Throws std::invalid_argument for
/// metric sizes that are not one per keypoint or bad enabled options, std::out_of_range for a
/// match out of range.
FeatureDatabase::Recognition KeepConsistentMatches(const FeatureDatabase& database,
                                                   const FrameFeatures& features,
                                                   const KeypointConsistencyOptions& options,
                                                   const std::vector<RatioMatch>& matches);

/// Matches a frame's features with `database` (counts unchanged). Throws std::invalid_argument
/// for a descriptor width that is not the database's, or as KeepConsistentMatches.
FrameRecognition MatchObjects(const FrameFeatures& features, const FeatureDatabase& database,
                              const core::PinholeCamera& camera,
                              const ObjectRecognitionOptions& options = {});

/// Both: `extractor` must give the database's descriptors; `depth` (CV_32FC1 metres of `grey`'s
/// size, or empty: unknown) gives the keypoints' metric sizes for the consistency check. Throws
/// as ExtractFrameFeatures and MatchObjects.
FrameRecognition RecognizeObjects(const cv::Mat& grey, const cv::Mat& depth,
                                  cv::Feature2D& extractor, const FeatureDatabase& database,
                                  const core::PinholeCamera& camera,
                                  const ObjectRecognitionOptions& options = {});

}  // namespace novelty::objects
