// Log-gamma, digamma and trigamma for the normal-gamma KL divergence (eq. 4.16, 4.18) and the
// gamma maximum-likelihood fit (eq. 2.14-2.17).
//
// The accurate functions shift the argument up by a fixed number of steps with the recurrences
//   ln Γ(z) = ln Γ(z+N) - ln(z (z+1) ... (z+N-1)),   ψ(z) = ψ(z+N) - Σ_{k<N} 1/(z+k)
// and evaluate the asymptotic (Stirling) series at z+N >= N. The shift count is fixed, so the same
// code is branch-free and runs on Eigen fixed-size arrays (vectorised) as well as on doubles.
// Measured accuracy for z in [1e-3, 1e6] (tests/maps/stats/special_functions_test.cc):
//   LogGamma: |error| < 2e-13·max(1, |ln Γ|), Digamma: < 1e-12, Trigamma: < 1e-12 relative.
//
// The thesis's GPU approximations are also provided, because shader code had no special functions:
//   eq. 4.22  Stirling's series for Γ(z) without shift (here in log form),
//   eq. 4.23  ψ(z) ≈ -1/z - γ + Σ_{n=1}^{5} (1/n - 1/(z+n)).
// Their error is large for the arguments the appearance map uses (α ≈ 0.5 ... 5, see eq. 4.10):
//   4.22 at z = 0.5: ln Γ off by 1.6e-2; at z = 2.5: 8.1e-7 (it improves quickly with z).
//   4.23 at z = 0.5: ψ off by 0.087; at z = 2.5: 0.374; the error grows like ln(z).
// They are therefore an option (NormalGammaKLOptions::fast_approximations), not the default.
#pragma once

#include "maps/stats/scalar_ops.h"

namespace novelty::stats {

/// Euler-Mascheroni constant γ.
inline constexpr double kEulerGamma = 0.57721566490153286061;

/// Number of recurrence steps before the asymptotic series. In double, 8 steps make the truncated
/// series below accurate to ~1e-14; float needs only ~1e-8, which 4 steps give (at x = 4 the first
/// omitted terms are 1e-10 for ln Γ and 3e-10 for ψ) at half the cost.
template <class S>
inline constexpr int kSpecialFunctionShift = sizeof(S) >= sizeof(double) ? 8 : 4;

/// ln Γ(z) for z > 0. T is double, float or an Eigen fixed-size array.
template <class T>
T LogGamma(const T& z) {
  using S = ScalarOf<T>;
  T product = z;
  T x = z + S(1);
  for (int k = 1; k < kSpecialFunctionShift<S>; ++k) {
    product = product * x;
    x = x + S(1);
  }
  // Stirling series at x = z + shift: (x-1/2) ln x - x + ln(2π)/2 + 1/(12x) - 1/(360x³) +
  // 1/(1260x⁵)
  // - 1/(1680x⁷) + 1/(1188x⁹) - 691/(360360x¹¹); the next term is < 2e-14 at x = 8.
  const T inv = S(1) / x;
  const T inv2 = inv * inv;
  const T series =
      inv *
      (S(1.0 / 12) + inv2 * (S(-1.0 / 360) +
                             inv2 * (S(1.0 / 1260) +
                                     inv2 * (S(-1.0 / 1680) +
                                             inv2 * (S(1.0 / 1188) + inv2 * S(-691.0 / 360360))))));
  return (x - S(0.5)) * Log(x) - x + S(0.91893853320467274178) + series - Log(product);
}

/// ψ(z) = d/dz ln Γ(z) for z > 0 (eq. 2.15).
template <class T>
T Digamma(const T& z) {
  using S = ScalarOf<T>;
  // Σ_k 1/(z+k) kept as one fraction num/den: one division instead of one per step.
  T num = Filled<T>(S(1)), den = z;
  T x = z + S(1);
  for (int k = 1; k < kSpecialFunctionShift<S>; ++k) {
    num = num * x + den;
    den = den * x;
    x = x + S(1);
  }
  const T shift_sum = num / den;
  // ψ(x) ~ ln x - 1/(2x) - 1/(12x²) + 1/(120x⁴) - 1/(252x⁶) + 1/(240x⁸) - 1/(132x¹⁰)
  // + 691/(32760x¹²); the next term is < 2e-14 at x = 8.
  const T inv = S(1) / x;
  const T inv2 = inv * inv;
  const T series =
      inv2 *
      (S(-1.0 / 12) +
       inv2 * (S(1.0 / 120) +
               inv2 * (S(-1.0 / 252) +
                       inv2 * (S(1.0 / 240) + inv2 * (S(-1.0 / 132) + inv2 * S(691.0 / 32760))))));
  return Log(x) - S(0.5) * inv + series - shift_sum;
}

/// ψ'(z), the trigamma function, for z > 0 (used by the Newton step of eq. 2.16).
template <class T>
T Trigamma(const T& z) {
  using S = ScalarOf<T>;
  T shift_sum = S(1) / (z * z);
  T x = z + S(1);
  for (int k = 1; k < kSpecialFunctionShift<S>; ++k) {
    shift_sum = shift_sum + S(1) / (x * x);
    x = x + S(1);
  }
  // ψ'(x) ~ 1/x + 1/(2x²) + 1/(6x³) - 1/(30x⁵) + 1/(42x⁷) - 1/(30x⁹) + 5/(66x¹¹)
  // - 691/(2730x¹³); the next term is < 4e-14 at x = 8.
  const T inv = S(1) / x;
  const T inv2 = inv * inv;
  const T tail =
      inv2 * (S(-1.0 / 30) +
              inv2 * (S(1.0 / 42) +
                      inv2 * (S(-1.0 / 30) + inv2 * (S(5.0 / 66) + inv2 * S(-691.0 / 2730)))));
  const T series = inv * (S(1) + inv * (S(0.5) + inv * (S(1.0 / 6) + tail)));
  return series + shift_sum;
}

/// ln Γ(z) by Stirling's series without shift, eq. 4.22 (thesis's GPU approximation).
template <class T>
T LogGammaStirling(const T& z) {
  using S = ScalarOf<T>;
  const T inv = S(1) / z;
  const T inv2 = inv * inv;
  const T series = inv * (S(1.0 / 12) + inv2 * (S(-1.0 / 360) + inv2 * S(1.0 / 1260)));
  return S(0.5) * (S(1.8378770664093454836) - Log(z)) + z * (Log(z) - S(1)) + series;
}

/// ψ(z) ≈ -1/z - γ + Σ_{n=1}^{5} (1/n - 1/(z+n)), eq. 4.23 (thesis's GPU approximation).
template <class T>
T DigammaTruncated(const T& z) {
  using S = ScalarOf<T>;
  T result = S(-1) / z - S(kEulerGamma);
  for (int n = 1; n <= 5; ++n) result = result + (S(1.0 / n) - S(1) / (z + S(n)));
  return result;
}

}  // namespace novelty::stats
