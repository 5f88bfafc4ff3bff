// The normal-gamma distribution over the mean μ and precision λ of one colour channel at one pixel
// (eq. 2.20, 4.2), and its Bayesian updates.
//
// Parameterisation as in the thesis: given λ, μ ~ N(τ, σ/λ); λ ~ Gamma(α, rate β). σ is therefore
// a variance *scale* (the inverse of the usual pseudo-count κ = 1/σ).
#pragma once

#include <string>
#include <vector>

#include "maps/stats/scalar_ops.h"

namespace novelty::stats {

/// Hyperparameters (α, β, τ, σ) of a normal-gamma distribution, eq. 4.2.
template <class T>
struct NormalGammaT {
  T alpha;  ///< shape of the precision's gamma distribution (> 0); "sample count" (eq. 4.4)
  T beta;   ///< rate of the precision's gamma distribution (> 0); "sum of squared deviations"
  T tau;    ///< expected value of the channel (τ)
  T sigma;  ///< variance scale of the mean given the precision (> 0)
};
using NormalGamma = NormalGammaT<double>;

/// The thesis's initial prior (4.3): α = 1, β = 1, τ = 0, σ = 5.
inline NormalGamma InitialPrior() {
  return {1.0, 1.0, 0.0, 5.0};
}

/// Throws std::invalid_argument naming `what` if α, β or σ is not a positive finite number or τ
/// is not finite.
void CheckNormalGamma(const NormalGamma& p, const std::string& what);

/// One-sample conjugate update, eq. 4.4-4.7.
NormalGamma UpdateOneSample(const NormalGamma& prior, double x);

/// N-sample conjugate update, eq. 2.22-2.25. Throws std::invalid_argument on an empty sample.
NormalGamma UpdateSamples(const NormalGamma& prior, const std::vector<double>& z);

/// Options of the update with forgetting and adaptive σ (eq. 4.8-4.13).
///
/// ξ, σ_min and σ_max are not given in the thesis. They are chosen from the scale of the data:
/// channels on 0…255, sensor noise of a few units. At steady state β/α approximates the channel's
/// variance v (eq. 4.9, 4.11), so eq. 4.8 multiplies σ by exp(ξ·v) each frame and σ settles at
/// 1 - exp(-ξ·v) (the weight a new observation gets in τ, eq. 4.12):
///   noise v = 4 (std 2):   ξ = 0.01 → weight 0.04 — the expected image averages ~25 frames;
///   change v = 2500 (std 50): exp(25) → σ_max — the new appearance is adopted within a frame.
struct ForgettingUpdateOptions {
  /// Forgetting factor f of eq. 4.10-4.11; α converges to 0.5/(1-f) = 2.5. Range (0, 1).
  double forgetting_factor = 0.8;
  /// ξ of eq. 4.8 (units: 1/channel-variance). Larger → faster re-learning after changes.
  double xi = 0.01;
  /// σ_min of eq. 4.8: keeps the expected image learning (weight ≥ σ_min/(σ_min+1) ≈ 1 %).
  double sigma_min = 0.01;
  /// σ_max of eq. 4.8: the thesis's initial σ = 5, the least certain state a pixel can be in.
  double sigma_max = 5.0;
  /// Floor of the variance β/α the posterior implies (units: channel², 0…255 scale): β ≥ α·v.
  /// Not in the thesis. With exactly constant input (saturated or clipped pixels) eq. 4.11 shrinks
  /// β as fⁿ until it underflows (NaN in float, a stuck 1e-7 in half floats, after which a change
  /// of one level costs ~38 of surprise per channel). An 8-bit camera cannot tell values closer
  /// than one level apart: rounding to a level is uniform noise of variance 1/12, the default.
  /// 0 = the thesis's update.
  double min_variance = 1.0 / 12.0;

  /// Throws std::invalid_argument naming the offending option.
  void Check() const;
};

/// σ_p of eq. 4.8: σ0 · exp(ξ / M01) clamped to [σ_min, σ_max], with M01 = α0/β0 (eq. 4.9), given
/// 1/α0: channels that share α (eq. 4.10 does not depend on the data) divide once for all.
template <class T>
T AdaptiveSigma(const NormalGammaT<T>& prior, const ForgettingUpdateOptions& o,
                const T& inv_alpha) {
  using S = ScalarOf<T>;
  const T grown = prior.sigma * Exp(S(o.xi) * prior.beta * inv_alpha);
  return Min(Max(grown, S(o.sigma_min)), S(o.sigma_max));
}

/// The same, computing 1/α0.
template <class T>
T AdaptiveSigma(const NormalGammaT<T>& prior, const ForgettingUpdateOptions& o) {
  using S = ScalarOf<T>;
  return AdaptiveSigma(prior, o, T(S(1) / prior.alpha));
}

/// Eq. 4.10-4.13 given σ_p (eq. 4.8). If tau_shift is given, it receives τ − τ0 computed without
/// cancellation (for NormalGammaKLWithShift).
template <class T>
NormalGammaT<T> UpdateWithSigma(const NormalGammaT<T>& prior, const T& x,
                                const ForgettingUpdateOptions& o, const T& sigma_p,
                                T* tau_shift = nullptr) {
  using S = ScalarOf<T>;
  const S f = S(o.forgetting_factor);
  const T weight = S(1) / (sigma_p + S(1));
  const T d = x - prior.tau;
  const T shift = sigma_p * weight * d;  // eq. 4.12 rewritten: τ = τ0 + σp (x − τ0) / (σp + 1)
  NormalGammaT<T> post;
  post.alpha = f * prior.alpha + S(0.5);                          // eq. 4.10
  post.beta = f * prior.beta + S(0.5) * d * d * weight;           // eq. 4.11
  post.beta = Max(post.beta, T(post.alpha * S(o.min_variance)));  // the quantisation floor
  post.tau = prior.tau + shift;                                   // eq. 4.12
  post.sigma = sigma_p * weight;                                  // eq. 4.13
  if (tau_shift) *tau_shift = shift;
  return post;
}

/// Update with forgetting factor and adaptive σ, eq. 4.8-4.13. T is double, float or an Eigen
/// fixed-size array (one lane per pixel). If tau_shift is given, it receives τ − τ0 computed
/// without cancellation (for NormalGammaKLWithShift).
template <class T>
NormalGammaT<T> UpdateWithForgetting(const NormalGammaT<T>& prior, const T& x,
                                     const ForgettingUpdateOptions& o, T* tau_shift = nullptr) {
  return UpdateWithSigma(prior, x, o, AdaptiveSigma(prior, o), tau_shift);
}

/// α after n updates with forgetting from α0 (closed form of the recursion eq. 4.10):
/// αn = fⁿ α0 + ½ (1 - fⁿ) / (1 - f) → 0.5 / (1 - f).
double AlphaAfterUpdates(double alpha0, int n, double forgetting_factor);

}  // namespace novelty::stats
