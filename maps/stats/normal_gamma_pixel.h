// One pixel of the update + surprise over parameter planes (normal_gamma_batch.h), written
// plainly with the templates of normal_gamma.h and normal_gamma_kl.h: the tail of the vectorised
// kernel's rows, and (in double) its reference.
#pragma once

#include <cmath>
#include <cstddef>
#include <limits>

#include "maps/stats/normal_gamma_batch.h"

namespace novelty::stats {

/// Pixel i of `c`: its update and surprise (as UpdateAndAccumulateSurprise) evaluated in precision
/// T, one pixel at a time. In float it finishes the rows the vectorised kernel leaves; in double
/// it is the reference the kernel is tested against.
template <class T>
void UpdateAndSurprisePixel(std::size_t i, const ChannelPlanes& c, float* surprise,
                const SurpriseBatchOptions& o) {
  const int channels = int(c.x.size());
  bool valid = true;
  for (int k = 0; k < channels; ++k) valid &= !std::isnan(c.x[k][i]);
  NormalGammaT<T> p0[kMaxChannels], p[kMaxChannels];
  T shift[kMaxChannels];
  for (int k = 0; k < channels; ++k) {
    const ConstNormalGammaPlanes& q = c.prior[std::size_t(k)];
    p0[k] = {T(q.alpha[i]), T(q.beta[i]), T(q.tau[i]), T(q.sigma[i])};
    p[k] = valid ? UpdateWithForgetting(p0[k], T(c.x[k][i]), o.update, &shift[k]) : p0[k];
  }
  // eq. 4.21: every channel's KL has its own α terms (α is shared, its terms are not).
  const T sum = T(channels) * NormalGammaKLAlphaTerms(p[0].alpha, p0[0].alpha, o.kl) +
                NormalGammaKLOtherTerms(p, p0, shift, channels);
  const T kl = !valid ? T(0) : sum < T(0) ? T(0) : sum;  // rounding below 0 → 0; NaN stays
  for (int k = 0; k < channels; ++k) {
    const NormalGammaPlanes& q = c.posterior[std::size_t(k)];
    q.alpha[i] = static_cast<float>(p[k].alpha);
    q.beta[i] = static_cast<float>(p[k].beta);
    q.tau[i] = static_cast<float>(p[k].tau);
    q.sigma[i] = static_cast<float>(p[k].sigma);
  }
  surprise[i] =
      valid ? surprise[i] + static_cast<float>(kl) : std::numeric_limits<float>::quiet_NaN();
}

}  // namespace novelty::stats
