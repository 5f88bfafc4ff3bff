// Camera poses over time and their interpolation to image timestamps (3.1.2): the tracker runs at
// 25 Hz, the cameras at their own rate, so every image gets the pose SLERPed between the two
// tracker poses around its timestamp. Optionally the poses in a short window are fitted by a
// local linear model first (rotation in the tangent space of the SLERP pose, translation as is),
// which averages the tracker noise down while following constant-velocity motion exactly.
#pragma once

#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

#include "core/eigen_abi.h"

namespace novelty::sensors {

struct TimedPose {
  double time = 0.0;
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
};

struct PoseInterpolationOptions {
  /// No pose is given at t when the tracker poses around t are further apart than this (s) — a
  /// run of dropouts — or t lies outside the recorded span.
  double max_gap = 0.25;
  /// Half-width (s) of the local linear fit (tricube weights); 0 = plain SLERP between the two
  /// neighbours, as the thesis. Measured on scenario (1) with 1 mm LED noise (median over image
  /// times): 0 → 0.43° / 0.87 mm, 0.2 → 0.21° / 0.41 mm, 0.4 → 0.14° / 0.29 mm, 0.6 → 0.12° /
  /// 0.25 mm. 0.4 s meets the 0.2° budget; longer windows start to round off stops and starts.
  double smoothing_half_window = 0.4;
};

/// SLERP of the rotations and linear interpolation of the translations, s ∈ [0, 1].
Eigen::Isometry3d InterpolatePose(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b, double s);

class PoseTrajectory {
 public:
  /// Poses in any order; they are sorted by time.
  explicit PoseTrajectory(std::vector<TimedPose> poses);

  /// The pose at `t`, or nullopt with the reason in `why`.
  std::optional<Eigen::Isometry3d> At(double t, const PoseInterpolationOptions& options,
                                      std::string* why) const;
  const std::vector<TimedPose>& poses() const { return poses_; }

 private:
  Eigen::Isometry3d LocalLinearFit(double t, const Eigen::Isometry3d& center,
                                   double half_window) const;
  std::vector<TimedPose> poses_;
};

}  // namespace novelty::sensors
