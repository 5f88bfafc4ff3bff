// Depth for camera observations that carry none (thesis 3.2): with `depth_source = stereo` the
// maps accept CObservationStereoImages and compute the left camera's depth by plane sweep and
// belief propagation (sensors/stereo), so a stereo robot feeds them without a converted rawlog.
// The default, `rgbd`, takes depth only from CObservation3DRangeScan.
#pragma once

#include <mrpt/obs/CObservation.h>
#include <mrpt/poses/CPose3D.h>

#include <optional>
#include <string>

#include "core/frame.h"
#include "sensors/stereo/stereo_depth.h"

namespace novelty::mrpt_plugins {

struct DepthSourceOptions {
  enum class Kind { kRgbd, kStereo };
  Kind kind = Kind::kRgbd;  ///< .ini `depth_source = rgbd | stereo`
  /// .ini `stereo_near`, `stereo_far` (m), `stereo_hypotheses`, `stereo_window` (pixels);
  /// defaults those of sensors/stereo (0.5, 5, 64, 5).
  sensors::StereoDepthOptions stereo;
};

/// The frame of a CObservationStereoImages with its depth computed by stereo (the left camera
/// is the reference; its pose robot_pose ⊕ cameraPose). Returns false when the source is not
/// stereo or the observation is not a stereo pair; throws std::invalid_argument naming the
/// sensor when the pair is unusable (no right image, sizes differ).
bool DecodeWithDepthSource(const mrpt::obs::CObservation& obs,
                           const std::optional<const mrpt::poses::CPose3D>& robot_pose,
                           const DepthSourceOptions& options, core::Frame& frame);

}  // namespace novelty::mrpt_plugins
