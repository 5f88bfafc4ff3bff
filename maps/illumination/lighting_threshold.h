// A decision threshold on the novelty Δ (eq. 6.24) from the training lightings alone, so that a
// user can deploy the map without ground truth (the thesis picks its operating points from ROCs
// over labelled frames, 6.4). Leave one lighting out: for each lighting m of a viewpoint, the
// invariant image and model are learnt from the other M − 1 (6.1.2, 6.2) and m is judged against
// them (6.3) as a new frame would be; m holds nothing new, so every pixel's Δ is a false alarm at
// any threshold below it. τ is the (1 − false_alarm_rate) quantile of the pooled held-out Δ: a new
// lighting like the training ones raises an alarm at about that share of its pixels. Held out,
// a lighting is judged by a model of one lighting fewer than the map's, so τ errs high (fewer
// false alarms than the target, not more).
#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "maps/illumination/illumination_model.h"
#include "maps/illumination/illumination_novelty.h"
#include "maps/illumination/invariant_image.h"
#include "maps/illumination/zernike_moments.h"

namespace novelty::illumination {

struct LightingThresholdOptions {
  /// Target share of a new, unchanged lighting's covered pixels with Δ above τ. 1 %: the issue's
  /// default, the thesis's ROCs' low end (6.4).
  double false_alarm_rate = 0.01;
  /// IlluminationMap: the viewpoints held out (evenly spread over the map's); each costs M
  /// invariant images. 0: no threshold is learnt.
  int viewpoints = 3;
};

/// What one viewpoint's lightings say, pooled by the caller when there are several viewpoints.
struct HeldOutNovelty {
  std::vector<float> values;                     ///< Δ of every held-out covered pixel
  std::vector<std::vector<float>> per_lighting;  ///< the same, per lighting (for its own rate)
};

/// Δ of each lighting against the other M − 1 (`images`, `coverage` as ComputeInvariantImage
/// takes them; M − 1 ≥ invariant.min_lightings). Throws std::invalid_argument naming the lighting
/// when too few images remain.
HeldOutNovelty HeldOutLightingNovelty(const std::vector<cv::Mat>& images,
                                      const std::vector<cv::Mat>& coverage,
                                      const InvariantImageOptions& invariant,
                                      const IlluminationModelOptions& model,
                                      const IlluminationNoveltyOptions& novelty,
                                      const ZernikeMoments& zernike);

/// The (1 − rate) quantile of `values` (the smallest τ with at most rate · n values above it);
/// throws std::invalid_argument for no values or a rate outside (0, 1).
double ThresholdAtFalseAlarmRate(std::vector<float> values, double rate);

/// Share of `values` above τ.
double ShareAbove(const std::vector<float>& values, double threshold);

}  // namespace novelty::illumination
