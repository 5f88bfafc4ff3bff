// Where the object database looks (thesis 5.1, "Computation of surprise map" and "Feature
// selection"): the surprise map is closed, then opened [Ser82] — regions of high surprise widen,
// isolated noise goes — and a region is flood-filled from its most surprising pixel down to
//   θ_S = μ_S + ξ·σ_S
// (μ_S, σ_S the mean and standard deviation of the map). The region's bounding box is the focus
// of attention; features are extracted inside it. ρ_S (eq. 5.5), the share of a descriptor's
// window above θ_S, decides which features may enter the database.
#pragma once

#include <opencv2/core.hpp>

namespace novelty::objects {

struct FocusOfAttentionOptions {
  /// ξ of θ_S = μ_S + ξ·σ_S (the thesis: 2).
  double xi = 2.0;
  /// Side (px) of the square structuring element of the closing and the opening; 0 skips both.
  /// The thesis gives none: 5 px at 320×240 closes gaps of a few pixels inside an object's
  /// surprise and removes specks of sensor noise smaller than that.
  int morphology_size = 5;
};

struct FocusOfAttention {
  cv::Mat surprise;        ///< the map after closing and opening, CV_32F, 0 where not covered
  double threshold = 0.0;  ///< θ_S
  cv::Point seed{-1, -1};  ///< the most surprising pixel; (−1, −1) if no pixel is covered
  cv::Rect box;            ///< the filled region's bounding box (empty if no pixel is covered)
  /// CV_8U, 255 in the filled region (8-connected, ≥ θ_S; GrowFocus adds the mask's pixels)
  cv::Mat region;
};

/// `surprise`: CV_32F, NaN where the map does not cover (those pixels are left out of μ_S and σ_S
/// and are never filled). Throws std::invalid_argument for another type or bad options.
FocusOfAttention FindFocusOfAttention(const cv::Mat& surprise,
                                      const FocusOfAttentionOptions& options = {});

/// The focus with `mask`'s pixels (CV_8U of the surprise map's size, non-zero) counted as
/// surprising: their surprise raised to θ_S where it is lower, so that SurprisingShare counts
/// them. Box, region, seed and θ_S stay. Throws std::invalid_argument for another mask.
FocusOfAttention MarkSurprising(const FocusOfAttention& focus, const cv::Mat& mask);

/// The focus grown over `mask`'s pixels (CV_8U of the surprise map's size, non-zero) as well as
/// its region: the region becomes the 8-connected part of region ∪ mask that holds the seed, the
/// box its bounding box. Surprise, θ_S and seed stay. A focus without a seed is returned as it
/// is. Throws std::invalid_argument for another mask.
FocusOfAttention GrowFocus(const FocusOfAttention& focus, const cv::Mat& mask);

/// ρ_S of eq. 5.5: the share of the pixels of the square window of side `window` (px) centred at
/// `center` and turned by `angle_rad` — the region a descriptor is computed from — whose
/// (closed and opened) surprise is at least θ_S. Pixels outside the image count as not
/// surprising. 0 for an empty window. Windows over 24 px are sampled on a 24 × 24 grid.
double SurprisingShare(const FocusOfAttention& focus, cv::Point2f center, float window,
                       float angle_rad);

}  // namespace novelty::objects
