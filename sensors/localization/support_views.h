// The support views of sequence registration (thesis 6.1.1): frames of a sequence m, localized
// both in its own frame (M, its odometry) and in the common frame (S, against the keyframes of
// the first sequence's odometry). Every `every`-th frame is tried, the first without a prior (or
// from a given one; DirectOdometry::Localize), each later one from the pose the last support
// view predicts: Q_last · M_j (eq. 6.1, 6.3). A frame that does not align — blank, occluded, too
// far from the prediction — is skipped with its reason, and the next one is tried; registration
// needs at least three (sequence_registration.h). Another lighting is no reason by itself
// (DirectOdometryOptions::prior_max_rms); the few views it biases, the registration's Cauchy
// refit lets go. Denser support views average the localization noise of each (2–4 mm): on
// I2 → I1, a support view every 8th frame gives Ceres 2.8 mm RMS against the common frame, every
// 23rd 3.3 mm with one support view 11.7 mm off.
#pragma once

#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <vector>

#include "core/eigen_abi.h"
#include "sensors/localization/direct_odometry.h"
#include "sensors/localization/sequence_registration.h"
#include "sensors/localization/stereo_pair.h"

namespace novelty::sensors {

struct SupportViewOptions {
  int every = 8;  ///< a support view is tried at frames 0, every, 2·every, … (≥ 1)
};

struct SupportViews {
  std::vector<SupportView> views;    ///< index = the frame's position in the sequence
  std::vector<std::string> skipped;  ///< "frame j: reason", for each frame that did not align
};

/// Localizes support views of the sequence `frames` (own poses `own_from_camera`, one per frame)
/// in the frame of `common`. `first_prior` (pose in the common frame) replaces the search for the
/// first support view (ORB, or alignment from every keyframe; carried to later frames by the own
/// odometry until one aligns). Throws std::invalid_argument if the counts differ or every < 1.
SupportViews LocalizeSupportViews(const DirectOdometry& common,
                                  const std::vector<StereoPair>& frames,
                                  const std::vector<Eigen::Isometry3d>& own_from_camera,
                                  const SupportViewOptions& options = {},
                                  const std::optional<Eigen::Isometry3d>& first_prior = {});

}  // namespace novelty::sensors
