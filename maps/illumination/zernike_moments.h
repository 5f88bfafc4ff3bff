// Zernike moments of a shape (thesis 6.3, eq. 6.21-6.23 [KH90]): the descriptor that matches a
// new frame's highlight or shadow region against the shapes the illumination-invariant map
// stored. d = (|A_nm|) for n ≤ max_order, 0 ≤ m ≤ n, n - m even — magnitudes, which a rotation
// of the shape leaves unchanged (|A_n,-m| = |A_nm| for a real shape, so m ≥ 0 suffices).
//
// Eq. 6.23 as written sums factorials of up to n = 120 with alternating signs: it overflows and
// cancels catastrophically long before that. Prata & Rusch's recursion in (n, m) is no cure: at
// n = 119, m = 59, ρ = 0.9 it returns 449 for -0.029. The radial polynomials come instead from
// Jacobi polynomials, R_nm(ρ) = (-1)^k ρ^m P_k^(m,0)(1 - 2ρ²) with k = (n - m)/2, by their
// three-term recurrence in k, stable like that of any orthogonal polynomials (the test checks
// orthogonality to n = 120 and values against exact rational arithmetic). Sampling: the shape's box
// is resampled to grid × grid cells (area-averaged, so a binary shape gives coverage fractions) and
// the square is inscribed in the unit disc (no pixel of the box is cut off). The grid's pixels lie
// on few distinct radii, so
//   A_nm = (n+1)/π Σ_rings R_nm(ρ_ring) · Σ_{pixels of the ring} f · e^{-imθ} · ΔA,
// all tables precomputed once (6.3: "have to be computed only once").
#pragma once

#include <complex>
#include <opencv2/core.hpp>
#include <vector>

namespace novelty::illumination {

struct ZernikeOptions {
  /// Highest order n. The thesis: 120 (3 721 moments). Not the default: on a grid a detection
  /// can afford (32 cells, 0.1-0.4 ms a descriptor; budget 20 ms a frame with several regions)
  /// the orders above about 40 are sampling noise, which outweighs the shape — a shape turned
  /// by 30° is then farther from itself than from another (ratio 0.7-1.1 at order 120; 0.34 at
  /// order 20; zernike_moments_test). Order 120 needs about 128 cells (ratio 0.68).
  int max_order = 20;
  /// Cells per side of the square around the unit disc the shape is resampled to.
  int grid = 32;
};

class ZernikeMoments {
 public:
  /// Throws std::invalid_argument for max_order outside [0, 200] or grid outside [2, 512].
  explicit ZernikeMoments(const ZernikeOptions& options = {});

  /// A_nm (eq. 6.21) of `shape` (one channel, any depth and size; 0 = background), ordered by n,
  /// then m = n mod 2, n mod 2 + 2, …, n.
  std::vector<std::complex<double>> Moments(const cv::Mat& shape) const;
  /// The descriptor d: |A_nm| in the same order.
  std::vector<float> Magnitudes(const cv::Mat& shape) const;

  int size() const { return int(orders_.size()); }
  const ZernikeOptions& options() const { return options_; }

  /// R_nm(ρ) by the recursion (n ≥ |m|, n - |m| even).
  static double Radial(int n, int m, double rho);
  /// Number of moments up to `max_order`.
  static int Count(int max_order);

 private:
  ZernikeOptions options_;
  std::vector<std::pair<int, int>> orders_;  // (n, m) per moment
  std::vector<int> ring_of_cell_;            // grid² cells → ring index
  int rings_ = 0;
  std::vector<double> radial_;               // moments × rings
  std::vector<std::complex<double>> phase_;  // grid² × (max_order + 1): e^{-imθ} ΔA
};

/// Euclidean distance of two descriptors (step 3c of 6.3); throws for different lengths.
double DescriptorDistance(const std::vector<float>& a, const std::vector<float>& b);

}  // namespace novelty::illumination
