// The Fast-Hessian detector of SURF (Bay et al. 2008, 3.1-3.3; thesis 5.1 uses SURF): the
// determinant of the Hessian of the image, with the second derivatives of Gaussians approximated
// by box filters of side L = 3·(2^(o+1)·(i+1) + 1) (octave o, interval i: 9, 15, 21, 27; 15, 27,
// 39, 51; …) evaluated in constant time on an integral image,
//   det H ≈ (Dxx·Dyy − (0.9·Dxy)²) / L⁴                                      (Bay eq. 4)
// maxima over 3×3×3 neighbours in position and scale within an octave, and the maximum's
// position and scale refined by fitting a 3-D quadratic (Brown & Lowe 2002). Octave o samples
// every 2^o·init_step pixels. The scale of a filter of side L is s = 1.2·L/9 (σ of the Gaussian
// it approximates).
#pragma once

#include <opencv2/core.hpp>
#include <vector>

namespace novelty::objects {

struct FastHessianOptions {
  /// Keypoints need det H above this, for an image scaled to 0…1 (the value of OpenSURF, the
  /// implementation the thesis's SURF [BETG08] was evaluated with; the thesis gives none).
  double threshold = 0.0004;
  int octaves = 4;    ///< octaves of four filter sizes each
  int init_step = 1;  ///< sampling step (px) of the first octave; doubles per octave
};

/// One scale-space maximum.
struct HessianPoint {
  cv::Point2f pt;        ///< image position (px, sub-pixel)
  float scale = 0.0f;    ///< s = 1.2·L/9 (px), L the interpolated filter side
  float response = 0.0f; ///< det H at the maximum
  int laplacian = 0;     ///< sign of Dxx + Dyy: +1 a dark blob on bright ground, −1 a bright one
  int octave = 0;
};

/// The box-filter determinant at image pixel (row, col) for filter side `size` (a multiple of 3,
/// odd), and the sign of the trace; `integral`: cv::integral of the 0…1 image, CV_64F.
float HessianDeterminant(const cv::Mat& integral, int row, int col, int size, int* laplacian);

/// The maxima of `integral` (cv::integral of the 0…1 image, CV_64F). With a `region` (px), only
/// those that may lie in it — within a sample of it — are searched, from responses computed
/// near it only: the same points there as a search of the whole image gives, for the cost of
/// the region (a focus of attention). Throws std::invalid_argument for a bad integral image or
/// options.
std::vector<HessianPoint> DetectFastHessian(const cv::Mat& integral,
                                            const FastHessianOptions& options = {},
                                            const cv::Rect& region = cv::Rect());

}  // namespace novelty::objects
