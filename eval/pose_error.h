// Camera pose error against ground truth, per frame and summarised: the rotation between
// estimate and truth (degrees, the angle of R_est⊤·R_true) and the distance between their
// positions (mm) — how novelty-poses reports a tracker's or visual localization's error.
#pragma once

#include <Eigen/Geometry>
#include <map>
#include <optional>

#include "core/eigen_abi.h"

namespace novelty::eval {

struct PoseErrorSummary {
  int frames = 0;  ///< frames with both an estimate and a true pose
  int last_frame = 0;
  double last_deg = 0.0, last_mm = 0.0;    ///< the last such frame's error
  double median_deg = 0.0, p95_deg = 0.0;  ///< rotation error's median and 95th percentile
  double median_mm = 0.0, p95_mm = 0.0;    ///< translation error's
};

/// The error of `estimated` against `truth` (both T_world_cam by frame) over the frames both
/// hold; nullopt when there are none.
std::optional<PoseErrorSummary> ComparePoses(const std::map<int, Eigen::Isometry3d>& estimated,
                                             const std::map<int, Eigen::Isometry3d>& truth);

}  // namespace novelty::eval
