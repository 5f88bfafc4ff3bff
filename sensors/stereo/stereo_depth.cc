#include "sensors/stereo/stereo_depth.h"

#include <algorithm>
#include <cmath>

namespace novelty::sensors {
namespace {

// Sub-plane refinement on the (window-averaged) matching cost around belief propagation's plane.
// The cost is a sum of absolute differences, V-shaped near its minimum, so the vertex comes from
// the equiangular (V) fit through three costs, which unlike a parabola is unbiased for it.
double RefineLabel(const CostVolume& cost, int x, int y, float bp_label) {
  const int l = int(std::lround(bp_label));
  if (l <= 0 || l + 1 >= cost.labels) return bp_label;
  const float a = cost(x, y, l - 1), b = cost(x, y, l), c = cost(x, y, l + 1);
  if (!(b <= a && b <= c) || (a == b && b == c)) return bp_label;  // no minimum of the cost here
  return l + 0.5 * (a - c) / (std::max(a, c) - b);
}

}  // namespace

StereoDepth ComputeStereoDepth(const cv::Mat& reference, const core::PinholeCamera& camera,
                               const std::vector<SweepView>& others,
                               const StereoDepthOptions& options) {
  BeliefPropagationOptions bp = options.propagation;
  bp.data_truncation = std::min(bp.data_truncation, options.sweep.truncation);
  const CostVolume volume = PlaneSweep(reference, camera, others, options.sweep);
  const Labeling labeling = RunBeliefPropagation(volume, bp);
  StereoDepth result{cv::Mat(reference.size(), CV_32F), labeling.confidence};
  for (int y = 0; y < reference.rows; ++y)
    for (int x = 0; x < reference.cols; ++x) {
      const bool keep = labeling.confidence.at<float>(y, x) >= options.min_confidence;
      const double label = RefineLabel(volume, x, y, labeling.label.at<float>(y, x));
      result.depth.at<float>(y, x) = keep ? float(DepthOfLabel(options.sweep, label)) : 0.0f;
    }
  return result;
}

}  // namespace novelty::sensors
