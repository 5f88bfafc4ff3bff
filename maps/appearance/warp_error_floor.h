// The variance a prior cannot go below because the warp that made it is not exact.
//
// A prior interpolated at a viewpoint (ch. 3) places each scene point where the views' poses and
// depths say; pose error (the LED tracker's 0.16° is about 0.8 px at 320×240), depth error
// (stereo) and resampling put it off by some δ pixels. To first order the colour the frame shows
// there is then τ(x + δ) ≈ τ(x) + ∇τ·δ: for isotropic δ of standard deviation s the prediction
// has the extra variance s²·|∇τ|² (one coordinate each: s²·(τx² + τy²)). Thesis 4.3.2 lets the
// map learn this uncertainty from the deviations it sees at edges (fig. 4.4d, 4.10). It does not
// with a tracker whose error is smoothed over 0.4 s: the frames of one pass agree with each other
// and with the views they make, so the map learns little at edges, and a later pass, whose poses
// are off in another direction, lands every edge about a pixel away (docs/appearance.md, "From
// sensor data"). The floor gives every warped prior at least the variance its own position error
// implies: β ≥ α·s²·|∇τ|² per channel (β/α is the variance the normal-gamma prior expects,
// eq. 4.9). It is a floor, not an addition, so it does not compound through the stored posterior
// (eq. 4.11 shrinks β by f each frame, the floor holds it). s can be learnt (MeasureWarpSigma).
#pragma once

#include <array>
#include <opencv2/core.hpp>

namespace novelty::appearance {

/// Raises beta[k] (rows `rows` of the frame, as CV_32FC1 planes of rows.size() rows) to at least
/// alpha·min(s²·|∇τ_k|², 255²/12), where ∇τ_k is the central difference of channel k of `tau` (CV_32FC3, the
/// whole prior, so that a tile's first and last rows see their neighbours; replicated at the
/// image border). A difference across a NaN (uncovered) neighbour counts as 0: there is no edge
/// the map knows of there. `sigma_px` = s ≥ 0; 0 leaves β as it is.
void FloorVarianceByWarpError(const cv::Mat& tau, const cv::Range& rows, double sigma_px,
                              const cv::Mat& alpha, const std::array<cv::Mat*, 3>& beta);

/// The position error (px) the prior shows against the frame, for learning s: along the prior's
/// gradient a shift δ changes the colour by |∇τ|·(n·δ), so e = (x − τ)/|∇τ| is the shift's
/// component along the gradient, of standard deviation s for isotropic shifts. Returns
/// 1.4826·median |e| (robust: a new object's pixels are outliers) over the pixels where the
/// luminance τ_Y (channel 0 of `tau`, CV_32FC3, NaN where not covered) changes by at least
/// `min_gradient` levels per pixel, so that sensor noise (a level or two) adds at most a tenth of
/// a pixel; NaN when fewer than `min_pixels` qualify. `observed_y`: the frame's Y, CV_32FC1.
double MeasureWarpSigma(const cv::Mat& observed_y, const cv::Mat& tau, double min_gradient = 16.0,
                        int min_pixels = 200);

}  // namespace novelty::appearance
