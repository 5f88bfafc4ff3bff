// Geometric verification of a recognised object (beyond the thesis, issue 26): the database keeps
// each learnt feature's 3-D place in the object's frame (the world frame where it was learnt);
// the 2-D–3-D pairs of a recognition — a selected keypoint matched to a database feature — must
// agree on one camera pose. An absolute-pose RANSAC (OpenGV: Kneip's P3P in a RANSAC loop) finds
// the pose most pairs agree on within a reprojection error; the object is verified if enough do,
// and its pose in the camera is reported.
#pragma once

#include <Eigen/Geometry>
#include <opencv2/core.hpp>
#include <vector>

#include "core/eigen_abi.h"
#include "core/pinhole_camera.h"

namespace novelty::objects {

struct PoseVerificationOptions {
  /// A pair agrees with a pose if the 3-D point reprojects within this (px) of the keypoint:
  /// the 2 px of eq. 5.1's static-feature test.
  double reprojection_px = 2.0;
  /// Pairs that must agree to verify; P3P needs 3 and a fourth to tell its solutions apart, and
  /// two more keep chance agreements of outliers out.
  int min_inliers = 6;
  int max_iterations = 500;
};

struct VerifiedPose {
  bool verified = false;
  int pairs = 0;  ///< 2-D–3-D pairs given with a known 3-D place
  /// Pairs that agree with the pose (RANSAC's count if it found fewer than min_inliers).
  int inliers = 0;
  /// With at least min_inliers found by RANSAC: the indices, into the pairs given (places
  /// unknown included), of those that agree with the pose — the refined one, or RANSAC's if
  /// that agrees with more; `inliers` is their number. Empty otherwise.
  std::vector<int> inlier_pairs;
  /// The object's frame in the camera's (maps object points into camera coordinates); identity
  /// unless verified. For an object learnt from a photo, from the homography and the camera's
  /// intrinsics, at the scale its photo was learnt at.
  Eigen::Isometry3d T_cam_object = Eigen::Isometry3d::Identity();
  /// An object learnt from a photo (planar_object_verification.h): its plane (x, y, 1) → the
  /// image's pixels; zero for other objects or unless a homography was found.
  Eigen::Matrix3d image_from_plane = Eigen::Matrix3d::Zero();
};

/// Pairs: `points_object[i]` (its 3-D place; NaN: unknown, left out) seen at `pixels[i]` by
/// `camera`. Deterministic (a fixed seed). Throws std::invalid_argument when the counts differ
/// or an option is out of range.
VerifiedPose VerifyObjectPose(const std::vector<Eigen::Vector3d>& points_object,
                              const std::vector<cv::Point2f>& pixels,
                              const core::PinholeCamera& camera,
                              const PoseVerificationOptions& options = {});

}  // namespace novelty::objects
