// Geometric verification of an object learnt from a photo (beyond the thesis): its features lie
// in the photo's plane (feature_database.h, ObjectInfo), so a true recognition maps them into the
// image by one homography. RANSAC over the 2-D–2-D pairs (OpenCV's findHomography) finds the
// homography most pairs agree on within a reprojection error; the object is verified if enough
// pairs do and the homography keeps the object's outline in front of the camera and unmirrored —
// a photo seen from its back or folded through the camera is no view of the object. Unlike the
// 3-D pose of object_pose_verification.h it needs no intrinsics: a photo's scale and the
// recognising camera's focal length are often unknown.
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <vector>

#include "core/eigen_abi.h"
#include "maps/objects/object_pose_verification.h"

namespace novelty::objects {

struct VerifiedHomography {
  bool verified = false;
  int pairs = 0;    ///< pairs given with a finite plane point
  int inliers = 0;  ///< pairs within options.reprojection_px of the homography's image
  /// The indices, into the pairs given, of those that agree (empty unless RANSAC found a
  /// homography with at least options.min_inliers of them).
  std::vector<int> inlier_pairs;
  /// Plane point (x, y, 1) → image pixel (homogeneous); zero unless RANSAC found one.
  Eigen::Matrix3d image_from_plane = Eigen::Matrix3d::Zero();
};

/// Pairs: `plane[i]` (the feature's place in the photo's plane; non-finite: left out) seen at
/// `pixels[i]`; `outline` the object's outline in the plane (at least 3 points) whose image must
/// be in front and keep its orientation. Deterministic. Throws std::invalid_argument when the
/// counts differ, the outline has fewer than 3 points, or an option is out of range
/// (VerifyObjectPose's bounds).
VerifiedHomography VerifyPlanarObject(const std::vector<Eigen::Vector2d>& plane,
                                      const std::vector<cv::Point2f>& pixels,
                                      const std::vector<Eigen::Vector2d>& outline,
                                      const PoseVerificationOptions& options = {});

/// `outline`'s image under `image_from_plane`.
std::vector<cv::Point2f> MapOutline(const Eigen::Matrix3d& image_from_plane,
                                    const std::vector<Eigen::Vector2d>& outline);

}  // namespace novelty::objects
