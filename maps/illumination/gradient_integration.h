// The image whose gradients best match a given gradient field, in least squares (eq. 6.10-6.13):
// pseudo-inverse filtering [Wei01]. With f^x = [1, -1] and f^y = [1, -1]^T as forward differences
//   gx(y, x) = r(y, x+1) - r(y, x),   gy(y, x) = r(y+1, x) - r(y, x),
// r minimises  Σ (f^x*r - gx)² + Σ (f^y*r - gy)²  over the constraints inside the image, whose
// normal equations are  (f^x*f̃^x + f^y*f̃^y) * r = gx*f̃^x + gy*f̃^y  (eq. 6.12-6.13): a Poisson
// equation with the image's border as a mirror (the last column of gx and the last row of gy
// join no pixel pair and are ignored). The thesis solves it with the FFT; mirroring the image
// makes the FFT's periodic pseudo-inverse exactly this least-squares solution, and for even sizes
// the mirrored FFT is a DCT-II, four times cheaper. The solution is unique up to a constant: it
// is returned with mean 0.
//
// IntegrateGradientsInRegion solves the same least squares over a region only (constraints with
// both pixels inside), by sparse Cholesky — for images that cover part of the frame (virtual
// views, masked objects; the formulation of Grosse et al. 2009's reference code), and as the
// independent check of the Fourier solution.
#pragma once

#include <opencv2/core.hpp>

namespace novelty::illumination {

/// gx, gy: CV_32FC1 of one size (at least 1 × 1), finite. Returns CV_32FC1 of that size, mean 0.
/// Throws std::invalid_argument otherwise.
cv::Mat IntegrateGradients(const cv::Mat& gx, const cv::Mat& gy);

/// The same over the pixels where `region` (CV_8UC1) is non-zero; each 4-connected part of it is
/// solved on its own with mean 0. Outside the region the result is 0. Throws
/// std::invalid_argument for mismatched sizes or types.
cv::Mat IntegrateGradientsInRegion(const cv::Mat& gx, const cv::Mat& gy, const cv::Mat& region);

}  // namespace novelty::illumination
