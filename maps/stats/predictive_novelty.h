// Predictive novelty (issue 52; beside the thesis's surprise, eq. 4.15): how improbable an
// observation x is under what the prior expects, −ln p(x | prior) in nats. With μ | λ ~ N(τ, σ/λ)
// and λ ~ Gamma(α, rate β) (eq. 4.2) and x | μ, λ ~ N(μ, 1/λ), x | λ ~ N(τ, (1 + σ)/λ), and
// integrating λ out leaves a Student-t with ν = 2α, location τ and scale² β(1 + σ)/α:
//   −ln p(x) = ln Γ(α) − ln Γ(α + ½) + ½ ln(2π β (1 + σ)) + (α + ½) ln(1 + (x − τ)² / (2β(1 + σ)))
// Surprise asks how much x changes the belief; predictive novelty how unexpected x is — the
// question a foreground detector answers. Summed over channels that share α (Y, Cb, Cr, eq.
// 4.10), the logarithms are taken of products, as the surprise kernel does (normal_gamma_kl.h).
#pragma once

#include "maps/stats/normal_gamma.h"
#include "maps/stats/special_functions.h"

namespace novelty::stats {

/// ln Γ(α) − ln Γ(α + ½), the α part of −ln p of one channel.
template <class T>
T PredictiveAlphaTerm(const T& alpha) {
  using S = ScalarOf<T>;
  return LogGamma(alpha) - LogGamma(T(alpha + S(0.5)));
}

/// −ln p(x | prior) of one channel (nats; x on the channel's scale, the density per unit of it).
template <class T>
T PredictiveNegLogDensity(const NormalGammaT<T>& p, const T& x) {
  using S = ScalarOf<T>;
  const T q = S(2) * p.beta * (S(1) + p.sigma);  // 2β(1 + σ)
  const T d = x - p.tau;
  return PredictiveAlphaTerm(p.alpha) + S(0.5) * Log(T(S(3.14159265358979323846) * q)) +
         (p.alpha + S(0.5)) * Log(T(S(1) + d * d / q));
}

/// The sum over `channels` channels observed together, which share α: `alpha_term` is
/// PredictiveAlphaTerm(α) (computed once for pixels of one α), two logarithms for all channels.
template <class T>
T PredictiveNegLogDensityChannels(const NormalGammaT<T>* p, const T* x, int channels,
                                  const T& alpha_term) {
  using S = ScalarOf<T>;
  T spread = x[0] * S(0) + S(1), tails = spread;
  for (int k = 0; k < channels; ++k) {
    const T q = S(2) * p[k].beta * (S(1) + p[k].sigma);
    const T d = x[k] - p[k].tau;
    spread = spread * (S(3.14159265358979323846) * q);
    tails = tails * (S(1) + d * d / q);
  }
  return S(channels) * alpha_term + S(0.5) * Log(spread) + (p[0].alpha + S(0.5)) * Log(tails);
}

/// The same sum as ½ ln U + (α + ½) ln V + offset, so that a plane of pixels needs two
/// logarithms a pixel, taken of whole planes (cv::log): α's Gamma functions by the recurrence
/// Γ(α+½)/Γ(α) = Γ(α+2½)/Γ(α+2) · α(α+1)/((α+½)(α+1½)) and the Stirling series of
/// ln Γ(z+½) − ln Γ(z) = ½ ln z − 1/(8z) + 1/(192z³) − 1/(640z⁵) + 17/(14336z⁷) + O(z⁻⁹) at
/// z = α + 2 ≥ 2 (the next term is below 1e-6 there):
///   U = Π_k π q_k / (z^C r^(2C)),  r = α(α+1)/((α+½)(α+1½)),  V = Π_k (1 + d_k²/q_k),
///   offset = −C·(the series' terms after ½ ln z),  q_k = 2β_k(1 + σ_k), d_k = x_k − τ_k.
template <class T>
void PredictiveLogArguments(const NormalGammaT<T>* p, const T* x, int channels, T& u, T& v,
                            T& offset) {
  using S = ScalarOf<T>;
  const T& a = p[0].alpha;
  const T z = a + S(2), iz = S(1) / z, iz2 = iz * iz;
  const T series =
      iz * (S(-1.0 / 8) + iz2 * (S(1.0 / 192) + iz2 * (S(-1.0 / 640) + iz2 * S(17.0 / 14336))));
  const T r = a * (a + S(1)) / ((a + S(0.5)) * (a + S(1.5)));
  T spread = z * S(0) + S(1), tails = spread, denominator = spread;
  for (int k = 0; k < channels; ++k) {
    const T q = S(2) * p[k].beta * (S(1) + p[k].sigma);
    const T d = x[k] - p[k].tau;
    spread = spread * (S(3.14159265358979323846) * q);
    tails = tails * (S(1) + d * d / q);
    denominator = denominator * (z * r * r);
  }
  u = spread / denominator;
  v = tails;
  offset = -S(channels) * series;
}

}  // namespace novelty::stats
