// Closed-form Kullback-Leibler divergence KL(p ‖ p0) of two normal-gamma distributions: Bayesian
// surprise of one channel at one pixel (eq. 4.14-4.20).
//
// The thesis writes KL = T1 + T2 + T3 + T4 + T5. Evaluated literally, T1 and T3 hold α·ln β terms
// that are large and cancel when posterior and prior are close (the common, unsurprising case).
// The same sum is regrouped here without changing its value:
//   KL = [ln Γ(α0) − ln Γ(α) + (α−α0) ψ(α)]            (≥ 0: ln Γ is convex)
//      + [α0 ln(β/β0) + α (β0/β − 1)]
//      + ½ [r − 1 − ln r],  r = σ/σ0                  (≥ 0)
//      + (τ − τ0)² α / (2 σ0 β)                        (≥ 0)
// so each bracket is small when the distributions are close, and float evaluation stays accurate.
// Checked against 2-D numerical integration of eq. 4.14 in normal_gamma_kl_test.cc.
#pragma once

#include "maps/stats/normal_gamma.h"
#include "maps/stats/special_functions.h"

namespace novelty::stats {

struct NormalGammaKLOptions {
  /// Use the thesis's GPU approximations of ln Γ and ψ (eq. 4.22-4.23) instead of the accurate
  /// functions. Default false: for the steady-state parameters of the appearance map (α = 2.5)
  /// eq. 4.23 is off by 0.37 in ψ, which shifts KL by about 0.37·|α−α0| — see special_functions.h.
  bool fast_approximations = false;
};

/// The first bracket above: it depends on α only, so channels that share α (eq. 4.10 does not
/// depend on the data) compute it once per pixel.
template <class T>
T NormalGammaKLAlphaTerms(const T& post_alpha, const T& prior_alpha,
                          const NormalGammaKLOptions& o = {}) {
  const T dalpha = post_alpha - prior_alpha;
  return o.fast_approximations
             ? T(LogGammaStirling(prior_alpha) - LogGammaStirling(post_alpha) +
                 dalpha * DigammaTruncated(post_alpha))
             : T(LogGamma(prior_alpha) - LogGamma(post_alpha) + dalpha * Digamma(post_alpha));
}

/// The other three brackets (β, σ and τ terms) summed over `channels` channels observed together
/// (eq. 4.21), which share α (eq. 4.10 does not depend on the data: prior[k].alpha and
/// post[k].alpha are the same for every k). Their logarithms are taken of products,
///   Σ_k α0 ln(β/β0)_k = −α0 ln Π_k (β0/β)_k,   Σ_k ln r_k = ln Π_k r_k,
/// two logarithms for any number of channels: ln is the costliest part of the per-pixel kernel,
/// and a product of a few ratios loses nothing that the single logarithms kept. The three
/// quotients of a channel share one division, 1/(β σ0) (divisions are the next costliest).
template <class T>
T NormalGammaKLOtherTerms(const NormalGammaT<T>* post, const NormalGammaT<T>* prior,
                          const T* tau_shift, int channels) {
  using S = ScalarOf<T>;
  T linear = tau_shift[0] * S(0), beta_ratios = linear + S(1), sigma_ratios = beta_ratios;
  for (int k = 0; k < channels; ++k) {
    const T inv = S(1) / (post[k].beta * prior[k].sigma);       // 1/(β σ0)
    const T beta_ratio = prior[k].beta * prior[k].sigma * inv;  // β0/β
    const T r = post[k].sigma * post[k].beta * inv;             // σ/σ0
    linear += post[k].alpha * (beta_ratio - S(1)) + S(0.5) * (r - S(1)) +
              S(0.5) * tau_shift[k] * tau_shift[k] * post[k].alpha * inv;
    beta_ratios *= beta_ratio;
    sigma_ratios *= r;
  }
  return linear - prior[0].alpha * Log(beta_ratios) - S(0.5) * Log(sigma_ratios);
}

/// The same for one channel.
template <class T>
T NormalGammaKLOtherTerms(const NormalGammaT<T>& post, const NormalGammaT<T>& prior,
                          const T& tau_shift) {
  return NormalGammaKLOtherTerms(&post, &prior, &tau_shift, 1);
}

/// KL(posterior ‖ prior), eq. 4.15, given the mean shift τ − τ0 separately. In float, τ − τ0
/// computed from the two τ values loses most digits when the shift is small against τ (a shift of
/// 0.01 at τ = 200 keeps three); an update knows the shift exactly (σp·(x − τ0)/(σp + 1),
/// eq. 4.12).
template <class T>
T NormalGammaKLWithShift(const NormalGammaT<T>& post, const NormalGammaT<T>& prior,
                         const T& tau_shift, const NormalGammaKLOptions& o = {}) {
  return NormalGammaKLAlphaTerms(post.alpha, prior.alpha, o) +
         NormalGammaKLOtherTerms(post, prior, tau_shift);
}

/// KL(posterior ‖ prior), eq. 4.15. T is double, float or an Eigen fixed-size array.
template <class T>
T NormalGammaKL(const NormalGammaT<T>& post, const NormalGammaT<T>& prior,
                const NormalGammaKLOptions& o = {}) {
  return NormalGammaKLWithShift(post, prior, T(post.tau - prior.tau), o);
}

/// Eq. 4.16-4.20 exactly as printed (T1 + … + T5), in double. For tests and documentation of the
/// regrouping above; use NormalGammaKL in code.
double NormalGammaKLAsPrinted(const NormalGamma& post, const NormalGamma& prior);

}  // namespace novelty::stats
