// Loopy belief propagation on the 4-connected pixel grid for labelings with a truncated linear
// smoothness cost, as Felzenszwalb & Huttenlocher 2006 (used by thesis 3.2):
//   E(f) = Σ_p λ·min(D_p(f_p), τ) + Σ_(p,q) min(s·|f_p − f_q|, d),
// min-sum messages computed in O(labels) by a distance transform, checkerboard (bipartite)
// updates, and a coarse-to-fine pyramid whose coarser levels sum the data costs of 2×2 blocks and
// hand their messages down as the finer level's initial messages.
#pragma once

#include <opencv2/core.hpp>

#include "sensors/stereo/cost_volume.h"

namespace novelty::sensors {

struct BeliefPropagationOptions {
  /// λ: weight of the data term (F&H's 0.07 for Σ|ΔRGB|-like costs is tuned for 0…255 grey
  /// values; ours are Σ over three channels, hence a third of it).
  float data_weight = 0.025f;
  /// τ: the data cost is truncated here before weighting (same units as the cost volume).
  float data_truncation = 60.0f;
  /// s: smoothness cost per label of difference between neighbours.
  float smoothness = 0.25f;
  /// d: the smoothness cost never exceeds this (lets depth jump at object borders).
  float smoothness_truncation = 1.2f;
  int levels = 5;      ///< pyramid levels (1 = single scale)
  int iterations = 4;  ///< message passes per level
};

struct Labeling {
  /// Label per pixel with sub-label refinement (parabola through the belief around the
  /// minimum), CV_32F.
  cv::Mat label;
  /// 0…1: how clearly the best label wins — the belief margin to the best label more than one
  /// step away, relative to the data-cost truncation λτ. CV_32F.
  cv::Mat confidence;
};

Labeling RunBeliefPropagation(const CostVolume& data, const BeliefPropagationOptions& options);

}  // namespace novelty::sensors
