// Statistics of the illumination images at one viewpoint (thesis 6.2): gamma distributions of
// their luminance and colour saturation (eq. 6.16, maximum likelihood), the information of each
// value (eq. 6.17), the threshold T_Y on the luminance's information (eq. 6.18), and the binary
// shapes of the regions above it — highlights and strong shadows, which 6.3 matches against a
// new frame's to tell lighting from change.
//
// Luminance and saturation are HSV's V and S of the linear illumination image L = exp(l̂)
// (color/hsv.h): V = max over the channels, S = 1 - min/max.
// What the thesis leaves open, decided here (eq. 6.17: "the luminance values of the digital
// illumination images are quantized ... the probability of a luminance value is approximated by
// the product of the probability density ... and the width of the quantization interval"): the
// width is one level of the stored 8-bit illumination image — 1/128 for the luminance, stored
// with 1 at 128 (novelty-invariant writes it so), 1/255 for the saturation (0…1). One width for
// every pixel: T_Y = mean/(1 - κ) is not shift-invariant, and a width that varied with the pixel
// would rank pixels by their surface's brightness too. Values are taken no smaller than half
// their width, in the fit and in the information, so that an exact 0 (a grey pixel's saturation,
// a black shadow) counts as the lowest level.
#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "maps/illumination/invariant_image.h"
#include "maps/illumination/missing_texture.h"
#include "maps/stats/gamma_ml_fit.h"
#include "maps/stats/tail_information.h"

namespace novelty::illumination {

struct IlluminationModelOptions {
  /// κ of T_Y = mean(i_Y) / (1 - κ) (eq. 6.18): 0.5 for Lambertian scenes, 0.2 with specular
  /// surfaces (6.4). Default: the Lambertian value.
  double kappa = 0.5;
  /// Width of the luminance's quantisation interval (eq. 6.17): one level of an 8-bit
  /// illumination image with 1 at 128.
  double luminance_step = 1.0 / 128.0;
  /// The same for the saturation (0…1 in 8 bits).
  double saturation_step = 1.0 / 255.0;
  /// Beyond the thesis: also learn how much of r̂'s texture lighting hides (missing_texture.h),
  /// whose information i_T joins i_Y and i_S in Δ (eq. 6.24). Lighting leaves r̂'s texture in
  /// the log image; an object on a textured surface removes it, also where its own colour is
  /// the surface's, which i_Y and i_S cannot see.
  bool missing_texture = false;
  MissingTextureOptions texture;
};

/// One image's luminance and saturation (CV_32FC1 each; the saturation is empty for one-channel
/// images).
struct IlluminationComponents {
  cv::Mat luminance, saturation;
};

struct IlluminationModel {
  stats::GammaFit luminance;   ///< a_Y, b_Y of eq. 6.16
  stats::GammaFit saturation;  ///< a_S, b_S (α = β = 0 for one-channel or colourless images)
  double luminance_step = 1.0 / 128.0;  ///< the widths it was learnt with (eq. 6.17)
  double saturation_step = 1.0 / 255.0;
  /// With IlluminationModelOptions::missing_texture (else empty): the hidden share h of r̂'s
  /// texture (HiddenTextureShare, ≥ 0) relative to its scale at the pixel, u = h / texture_scale,
  /// as the training images show it; i_T = −ln P(u' ≥ u). Its tail information saturates at
  /// ln(N + 1) rather than growing with u, so that i_T cannot outweigh i_Y and i_S.
  stats::TailTable texture;
  int texture_block = 7;       ///< MissingTextureOptions::block it was learnt with
  double texture_floor = 0.0;  ///< the energy floor of HiddenTextureShare: r̂'s mean energy
  /// CV_32FC1: per pixel, the largest |h| of the training images plus the mean |h| of all.
  /// Where the surface's normal changes (an object's outline, a fold) lighting changes the
  /// contrast either way and hides texture on its own; the model learns how much, per pixel.
  cv::Mat texture_scale;
  double mean_information = 0.0;  ///< mean of i_Y over all images' covered pixels
  double threshold = 0.0;         ///< T_Y (eq. 6.18)
  /// Per training image, CV_8UC1: 255 where i_Y > T_Y (highlights and strong shadows).
  std::vector<cv::Mat> shapes;
};

/// Luminance and saturation of a log illumination image (CV_32FC1 or CV_32FC3).
IlluminationComponents ComputeIlluminationComponents(const cv::Mat& log_illumination);

/// i = -log(p(max(x, Δ/2)) · Δ) per pixel (eq. 6.17) under a fitted gamma distribution; values
/// CV_32FC1, Δ > 0. Returns CV_32FC1.
cv::Mat InformationMap(const cv::Mat& values, double step, const stats::GammaFit& fit);

/// Fits the model to the illumination images of `invariant` (`coverage` as given to
/// ComputeInvariantImage). Throws std::invalid_argument for κ outside [0, 1), widths ≤ 0,
/// coverage masks that do not match the illumination images, or illumination images that do
/// not vary (identical lightings: no model of lighting can be learnt).
IlluminationModel LearnIlluminationModel(const InvariantImage& invariant,
                                         const std::vector<cv::Mat>& coverage = {},
                                         const IlluminationModelOptions& options = {});

}  // namespace novelty::illumination
