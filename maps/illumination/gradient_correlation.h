// Change detection by normalised gradient correlation (NGC) [OH07], thesis eq. 2.35-2.36, one
// of the two baselines of 6.4: in a block around each pixel
//   ρ = Σ |∂x I1 ∂x I2 + ∂y I1 ∂y I2| / sqrt(Σ |∇I1|² · Σ |∇I2|²),
// unchanged by I2 = α I1 + β and by gradients whose sign shading flips (the absolute value);
// the change measure is 1 - ρ (6.4), on three resolution layers, averaged. Where both blocks
// are flat (no gradient energy) nothing can have changed: ρ = 1; where one is flat and the
// other not, ρ = 0.
#pragma once

#include <opencv2/core.hpp>

namespace novelty::illumination {

struct GradientCorrelationOptions {
  /// Side of the block in pixels at every layer (odd).
  int block = 5;
  /// Resolution layers (each half the previous one's size) whose 1 - ρ are averaged [OH07: 3].
  int layers = 3;
  /// Gradient energy (Σ |∇I|² over a block, grey levels²) below which a block counts as flat.
  double flat_energy = 1.0;
};

/// 1 - ρ per pixel, CV_32FC1 in [0, 1], of two images of one size and type (grey or RGB, any
/// depth; colour is averaged to grey first). Throws std::invalid_argument otherwise.
cv::Mat GradientCorrelationChange(const cv::Mat& observation, const cv::Mat& reference,
                                  const GradientCorrelationOptions& options = {});

}  // namespace novelty::illumination
