// Feature matching along epipolar lines (thesis 5.1, "3D reconstruction of features"): a feature
// of the reference (centre) image is matched to the other camera's features that lie on its
// epipolar line — those whose rays meet its ray within the epipolar tolerance, at a depth in
// range (Triangulate) — by descriptor, with the ratio test the object database uses; its 3-D
// position is the rays' midpoint. The matched descriptor is d_m of eq. 5.2.
#pragma once

#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <vector>

#include "core/eigen_abi.h"
#include "sensors/localization/stereo_pair.h"
#include "sensors/localization/stereo_triangulation.h"

namespace novelty::sensors {

struct EpipolarFeatureMatch {
  int reference = -1;  ///< row / keypoint index in the reference image
  int other = -1;      ///< … in the other image
  Eigen::Vector3d p_reference = Eigen::Vector3d::Zero();  ///< in the reference camera's frame
  float distance = 0.0f;                                   ///< descriptor distance
};

/// Matches of the reference features (keypoints and CV_32F descriptors, one row each) among the
/// other image's; only `pair`'s cameras and rig offset are used. The nearest on-line candidate
/// must be nearer than `ratio` × the second-nearest on-line candidate — or, when it is the only
/// one on the line, than `ratio` × the second-nearest of all the other image's features (a lone
/// candidate is no evidence by itself). Throws std::invalid_argument when counts or descriptor
/// widths disagree.
std::vector<EpipolarFeatureMatch> MatchAlongEpipolarLines(
    const StereoPair& pair, const std::vector<cv::KeyPoint>& reference_keypoints,
    const cv::Mat& reference_descriptors, const std::vector<cv::KeyPoint>& other_keypoints,
    const cv::Mat& other_descriptors, const StereoTriangulationOptions& triangulation = {},
    double ratio = 0.65);

}  // namespace novelty::sensors
