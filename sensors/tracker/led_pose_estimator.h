// Camera pose from one LED tracker sample (thesis 3.1.2, eq. 3.5): the calibrated plate LEDs are
// fitted to the measured ones by the SVD (rigid_fit.h) — with three or four LEDs; the thesis uses
// LEDs 1–3 for the rotation and LED 4 for the translation, fitting all seen LEDs at once is the
// least-squares version of the same — and the camera follows from the fixed plate mount.
#pragma once

#include <Eigen/Geometry>
#include <optional>
#include <string>

#include "core/eigen_abi.h"
#include "sensors/tracker/led_plate.h"

namespace novelty::sensors {

struct LedPoseOptions {
  /// A fit whose RMS residual exceeds this is rejected: a reflection, a swapped or a wrongly
  /// measured LED (m). About 5× the tracker's 1 mm noise.
  double max_rms = 0.005;
};

struct LedPose {
  double time = 0.0;
  Eigen::Isometry3d world_from_camera = Eigen::Isometry3d::Identity();
  int leds_used = 0;
  double rms = 0.0;  ///< fit residual (m)
};

/// The camera pose of `sample`, or nullopt with the reason in `why` (fewer than three LEDs seen,
/// residual too large, degenerate geometry).
std::optional<LedPose> EstimateCameraPose(const LedPlate& plate, const LedSample& sample,
                                          const LedPoseOptions& options, std::string* why);

}  // namespace novelty::sensors
