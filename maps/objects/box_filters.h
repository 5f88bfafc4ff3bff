// Box sums over an integral image (cv::integral, CV_64F, one row and column more than the image),
// and the Haar wavelet responses SURF builds on (Bay et al. 2008, 3.1 and 4.1). Rectangles reaching
// past the image are clipped to it: what lies outside counts as 0.
#pragma once

#include <algorithm>
#include <cmath>
#include <opencv2/core.hpp>

namespace novelty::objects {

/// The integral image (CV_64F, a row and column more) of an image on the 0…1 scale the
/// detector's threshold assumes: grey or BGR, CV_8U (0…255, scaled) or CV_32F / CV_64F (0…1).
/// Throws cv::Exception for other images.
cv::Mat UnitIntegral(cv::InputArray image);

/// Sum of the image over rows [row, row + rows) and columns [col, col + cols).
inline double BoxSum(const cv::Mat& integral, int row, int col, int rows, int cols) {
  const int h = integral.rows - 1, w = integral.cols - 1;
  const int r0 = std::clamp(row, 0, h), r1 = std::clamp(row + rows, 0, h);
  const int c0 = std::clamp(col, 0, w), c1 = std::clamp(col + cols, 0, w);
  if (r1 <= r0 || c1 <= c0) return 0.0;
  return integral.at<double>(r1, c1) - integral.at<double>(r0, c1) - integral.at<double>(r1, c0) +
         integral.at<double>(r0, c0);
}

/// Haar wavelet of side `size` (even) centred at (row, col): right half minus left half.
inline double HaarX(const cv::Mat& integral, int row, int col, int size) {
  const int h = size / 2;
  return BoxSum(integral, row - h, col, size, h) - BoxSum(integral, row - h, col - h, size, h);
}

/// Haar wavelet of side `size` (even) centred at (row, col): bottom half minus top half.
inline double HaarY(const cv::Mat& integral, int row, int col, int size) {
  const int h = size / 2;
  return BoxSum(integral, row, col - h, h, size) - BoxSum(integral, row - h, col - h, h, size);
}

/// Both Haar responses of side `size` (even) centred at the sub-pixel point (x, y) (pixel centres
/// at integers). A wavelet of even side centred at (col, row) in BoxSum's terms spans pixels
/// col − size/2 … col + size/2 − 1, so its centre lies at col − 0.5: the response at (x, y) is the
/// bilinear blend of the four wavelets around (x + 0.5, y + 0.5). Rounding the point instead would
/// shift every sample by up to half a pixel, differently for a rotated copy of the image. The
/// blend of box sums is the box sum over the bilinearly interpolated integral image, so both
/// wavelets take 9 interpolated corners (the 3 × 3 grid of their boxes' corners), clipped to the
/// image as BoxSum clips.
inline void HaarAt(const cv::Mat& integral, float x, float y, int size, float& rx, float& ry) {
  const float u = x + 0.5f, v = y + 0.5f;
  const int c = int(std::floor(u)), r = int(std::floor(v)), h = size / 2;
  const float fx = u - float(c), fy = v - float(r);
  const int last_row = integral.rows - 1, last_col = integral.cols - 1;
  double corner[3][3];  // rows r − h, r, r + h × columns c − h, c, c + h
  for (int i = 0; i < 3; ++i) {
    const int r0 = std::clamp(r + (i - 1) * h, 0, last_row);
    const int r1 = std::clamp(r + (i - 1) * h + 1, 0, last_row);
    const double* row0 = integral.ptr<double>(r0);
    const double* row1 = integral.ptr<double>(r1);
    for (int j = 0; j < 3; ++j) {
      const int c0 = std::clamp(c + (j - 1) * h, 0, last_col);
      const int c1 = std::clamp(c + (j - 1) * h + 1, 0, last_col);
      corner[i][j] = (1 - fy) * ((1 - fx) * row0[c0] + fx * row0[c1]) +
                     fy * ((1 - fx) * row1[c0] + fx * row1[c1]);
    }
  }
  const auto box = [&](int i0, int j0, int i1, int j1) {  // corners (i0, j0) … (i1, j1)
    return corner[i1][j1] - corner[i0][j1] - corner[i1][j0] + corner[i0][j0];
  };
  rx = float(box(0, 1, 2, 2) - box(0, 0, 2, 1));  // right half − left half
  ry = float(box(1, 0, 2, 2) - box(0, 0, 1, 2));  // bottom half − top half
}

}  // namespace novelty::objects
