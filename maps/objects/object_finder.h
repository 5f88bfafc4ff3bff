// "What known objects are in this image, and where?" — the list a robot acts on, from the object
// database of thesis ch. 5 (learnt by the robot where surprise pointed, or from photos,
// photo_object_learner.h): the frame's features are matched with the database (eq. 5.4's ratio
// matching, object_recognition.h), each object with matches is verified geometrically (a 3-D pose
// or, for a photo's object, a homography), and per object name the best class is listed with its
// outline in the image and, where the frame has depth, its place.
#pragma once

#include <Eigen/Geometry>
#include <limits>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "core/eigen_abi.h"
#include "core/pinhole_camera.h"
#include "maps/objects/object_recognition.h"

namespace novelty::objects {

struct ObjectFinderOptions {
  ObjectFinderOptions() { recognition.verify = true; }
  /// Matching and verification; verify is on (an object is listed as verified only if its
  /// matches agree on one pose or homography), verify_nearest must stay 0.
  ObjectRecognitionOptions recognition;
  /// An object not verified is still listed, as a candidate, from this many matches at distinct
  /// places: chance matches of an absent object's features with the ratio test at 0.65 stay
  /// far fewer.
  int min_matches = 10;
};

struct FoundObject {
  int object = -1;   ///< the database class listed for its name
  std::string name;  ///< FeatureDatabase::DisplayName
  /// Its matches (eq. 5.4's N_k) at distinct places (DistinctPlaces): several database
  /// features matching one keypoint, or keypoints of one blob, count once.
  int matches = 0;
  bool verified = false;
  int inliers = 0;  ///< matches at distinct places that agree (VerifiedPose::inliers)
  /// In the image's pixels: a verified photo object's outline mapped by its homography;
  /// otherwise the box of its agreeing keypoints (of its matched ones when not verified).
  std::vector<cv::Point2f> outline;
  /// Camera coordinates (m) of the object: the median of its agreeing (or matched) keypoints'
  /// back-projections where the frame's depth is known; NaN without depth there.
  Eigen::Vector3d place = Eigen::Vector3d::Constant(std::numeric_limits<double>::quiet_NaN());
  /// Verified: the object's frame in the camera's (VerifiedPose::T_cam_object).
  Eigen::Isometry3d T_cam_object = Eigen::Isometry3d::Identity();
};

/// The objects of `database` found in a frame with `features` (ExtractFrameFeatures with the
/// database's extractor) seen by `camera`, and `depth` (CV_32FC1 metres of the camera's size, 0
/// unknown; empty: none): verified ones first, then by inliers and matches. Throws as
/// MatchObjects, and std::invalid_argument for a depth of another size or type, min_matches < 1
/// or verify_nearest other than 0.
std::vector<FoundObject> FindObjects(const FrameFeatures& features, const cv::Mat& depth,
                                     const FeatureDatabase& database,
                                     const core::PinholeCamera& camera,
                                     const ObjectFinderOptions& options = {});

}  // namespace novelty::objects
