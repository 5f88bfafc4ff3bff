// Change detection by normalised gradient correlation (NGC) [OH07], thesis eq. 2.35-2.36, one
// of the two baselines of 6.4: in a block around each pixel
//   ρ = Σ |∂x I1 ∂x I2 + ∂y I1 ∂y I2| / sqrt(Σ |∇I1|² · Σ |∇I2|²),
// unchanged by I2 = α I1 + β and by gradients whose sign shading flips (the absolute value);
// the change measure is 1 - ρ (6.4), on three resolution layers, averaged. On plain surfaces
// the gradients are camera noise, whose correlation is random; the sums are therefore
// regularised by the energy c noise gives a block,
//   ρ = (Σ |∇I1·∇I2| + c) / sqrt((Σ |∇I1|² + c) (Σ |∇I2|² + c)),
// so that two plain blocks correlate (ρ → 1), a plain and a structured one do not (ρ → 0), and
// structure far above the noise is compared as eq. 2.36 compares it.
#pragma once

#include <opencv2/core.hpp>

namespace novelty::illumination {

struct GradientCorrelationOptions {
  /// Side of the block in pixels at every layer (odd).
  int block = 5;
  /// Resolution layers (each half the previous one's size) whose 1 - ρ are averaged [OH07: 3].
  int layers = 3;
  /// c: the gradient energy of a block of camera noise (Σ |∇I|², grey levels², Sobel gradients
  /// / 8, of the channel mean). Noise of σ grey levels a channel gives 0.375 σ²/3 a pixel of the
  /// mean of three channels: 3.1 for a 5 × 5 block at σ = 1, the simulator's and a good camera's
  /// noise.
  double noise_energy = 3.1;
};

/// 1 - ρ per pixel, CV_32FC1 in [0, 1], of two images of one size and type (grey or RGB, any
/// depth; colour is averaged to grey first). Throws std::invalid_argument otherwise.
cv::Mat GradientCorrelationChange(const cv::Mat& observation, const cv::Mat& reference,
                                  const GradientCorrelationOptions& options = {});

}  // namespace novelty::illumination
