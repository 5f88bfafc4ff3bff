// Dense depth for the reference camera of a stereo or trinocular rig (thesis 3.2): plane-sweep
// costs (plane_sweep.h) regularised by belief propagation (belief_propagation.h); the winning
// plane per pixel, refined between planes, gives the depth.
#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "sensors/stereo/belief_propagation.h"
#include "sensors/stereo/plane_sweep.h"

namespace novelty::sensors {

struct StereoDepthOptions {
  PlaneSweepOptions sweep;
  BeliefPropagationOptions propagation;
  /// Pixels whose confidence is below this get depth 0 (unknown). 0 keeps every pixel.
  float min_confidence = 0.0f;
};

struct StereoDepth {
  cv::Mat depth;       ///< CV_32F metres along +Z, 0 = unknown
  cv::Mat confidence;  ///< CV_32F 0…1 (belief_propagation.h)
};

/// Throws std::invalid_argument for inconsistent input (plane_sweep.h).
StereoDepth ComputeStereoDepth(const cv::Mat& reference, const core::PinholeCamera& camera,
                               const std::vector<SweepView>& others,
                               const StereoDepthOptions& options);

}  // namespace novelty::sensors
