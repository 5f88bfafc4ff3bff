#include "maps/appearance/warp_error_floor.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

namespace novelty::appearance {

namespace {

// Central differences of channel k of τ at column x: along the row (neighbours clamped to columns
// 0…last_col) and across the rows `up` and `down`. NaN next to an uncovered pixel.
inline void CentralDifferences(const cv::Vec3f* up, const cv::Vec3f* row, const cv::Vec3f* down,
                               int x, int last_col, int k, float& gx, float& gy) {
  gx = 0.5f * (row[std::min(x + 1, last_col)][k] - row[std::max(x - 1, 0)][k]);
  gy = 0.5f * (down[x][k] - up[x][k]);
}

// 0 for a difference across an uncovered neighbour: there is no edge the map knows of there.
inline float CoveredOrZero(float d) { return std::isfinite(d) ? d : 0.0f; }

// The most a floor asks for: the variance of a channel value known only to lie in 0…255 (a
// uniform distribution). Steeper gradients than that would add no information, and β of this
// size still fits a half float (α ≤ 2.5 at steady state: β ≤ 1.4·10⁴ < 65504).
constexpr float kMaxVariance = 255.0f * 255.0f / 12.0f;

}  // namespace

void FloorVarianceByWarpError(const cv::Mat& tau, const cv::Range& rows, double sigma_px,
                              const cv::Mat& alpha, const std::array<cv::Mat*, 3>& beta) {
  if (!(sigma_px >= 0.0 && std::isfinite(sigma_px))) {
    throw std::invalid_argument("FloorVarianceByWarpError: sigma_px must be finite and >= 0");
  }
  if (sigma_px == 0.0) return;
  if (tau.type() != CV_32FC3 || rows.start < 0 || rows.end > tau.rows ||
      alpha.type() != CV_32FC1 || alpha.rows != rows.size() || alpha.cols != tau.cols) {
    throw std::invalid_argument("FloorVarianceByWarpError: planes do not match");
  }
  const float s2 = float(sigma_px * sigma_px);
  const int cols = tau.cols, last_row = tau.rows - 1, last_col = cols - 1;
  for (int y = rows.start; y < rows.end; ++y) {
    const cv::Vec3f* up = tau.ptr<cv::Vec3f>(std::max(y - 1, 0));
    const cv::Vec3f* row = tau.ptr<cv::Vec3f>(y);
    const cv::Vec3f* down = tau.ptr<cv::Vec3f>(std::min(y + 1, last_row));
    const float* a = alpha.ptr<float>(y - rows.start);
    std::array<float*, 3> b;
    for (int k = 0; k < 3; ++k) b[std::size_t(k)] = beta[std::size_t(k)]->ptr<float>(y - rows.start);
    for (int x = 0; x < cols; ++x) {
      for (int k = 0; k < 3; ++k) {
        float gx, gy;
        CentralDifferences(up, row, down, x, last_col, k, gx, gy);
        gx = CoveredOrZero(gx), gy = CoveredOrZero(gy);
        float& bk = b[std::size_t(k)][x];
        bk = std::max(bk, a[x] * std::min(s2 * (gx * gx + gy * gy), kMaxVariance));
      }
    }
  }
}

double MeasureWarpSigma(const cv::Mat& observed_y, const cv::Mat& tau, double min_gradient,
                        int min_pixels) {
  if (observed_y.type() != CV_32FC1 || tau.type() != CV_32FC3 || observed_y.size() != tau.size()) {
    throw std::invalid_argument("MeasureWarpSigma: planes do not match");
  }
  const float g_min2 = float(min_gradient * min_gradient);
  const int last_col = tau.cols - 1;
  std::vector<float> shifts;
  for (int y = 1; y + 1 < tau.rows; ++y) {
    const cv::Vec3f* up = tau.ptr<cv::Vec3f>(y - 1);
    const cv::Vec3f* row = tau.ptr<cv::Vec3f>(y);
    const cv::Vec3f* down = tau.ptr<cv::Vec3f>(y + 1);
    const float* x = observed_y.ptr<float>(y);
    for (int u = 1; u < last_col; ++u) {
      float gx, gy;
      CentralDifferences(up, row, down, u, last_col, 0, gx, gy);
      const float g2 = gx * gx + gy * gy;  // NaN next to an uncovered pixel: not taken
      if (!(g2 >= g_min2)) continue;
      const float e = std::abs(x[u] - row[u][0]) / std::sqrt(g2);
      if (std::isfinite(e)) shifts.push_back(e);
    }
  }
  if (int(shifts.size()) < min_pixels) return std::numeric_limits<double>::quiet_NaN();
  auto mid = shifts.begin() + std::ptrdiff_t(shifts.size() / 2);
  std::nth_element(shifts.begin(), mid, shifts.end());
  return 1.4826 * double(*mid);
}

}  // namespace novelty::appearance
