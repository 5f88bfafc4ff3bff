// Per-pixel update + surprise over whole parameter planes: the inner loop of the appearance map.
//
// Planes are structure-of-arrays float buffers (one per hyperparameter), as the map stores them.
// The kernel evaluates the templates of normal_gamma.h and normal_gamma_kl.h (UpdateWithForgetting,
// the KL's α terms and other terms) 32 pixels at a time in float with Eigen fixed-size arrays
// (SIMD log/exp); the same templates one pixel at a time in double (normal_gamma_pixel.h) are the
// reference it is tested against (normal_gamma_batch_test.cc). Pixel blocks run on OpenCV's
// thread pool.
#pragma once

#include <cstddef>
#include <vector>

#include "maps/stats/normal_gamma.h"
#include "maps/stats/normal_gamma_kl.h"

namespace novelty::stats {

/// Read-only view of n pixels of (α, β, τ, σ) planes.
struct ConstNormalGammaPlanes {
  const float* alpha;
  const float* beta;
  const float* tau;
  const float* sigma;
};

/// Writable view of n pixels of (α, β, τ, σ) planes.
struct NormalGammaPlanes {
  float* alpha;
  float* beta;
  float* tau;
  float* sigma;
};

struct SurpriseBatchOptions {
  ForgettingUpdateOptions update;  ///< eq. 4.8-4.13 options
  NormalGammaKLOptions kl;         ///< eq. 4.15 options
};

/// Channels observed together at the same pixels (Y, Cb, Cr): their α planes are one plane
/// (eq. 4.10 does not depend on the data), so prior[k].alpha must be the same pointer for every
/// k, and posterior[k].alpha too. At most kMaxChannels channels.
struct ChannelPlanes {
  std::vector<const float*> x;                // observation per channel
  std::vector<ConstNormalGammaPlanes> prior;  // per channel, α shared
  std::vector<NormalGammaPlanes> posterior;   // per channel, α shared; may alias prior
};
inline constexpr int kMaxChannels = 4;

/// For each of n pixels i and each channel k: posterior = UpdateWithForgetting(prior, x) and
/// surprise[i] += Σ_k KL(posterior ‖ prior) (eq. 4.21 over channels). The KL's α terms are the
/// same for all channels: computed once and counted once per channel. A pixel with NaN in any
/// channel (no data) keeps its prior as posterior and gets NaN surprise, so it stays recognisably
/// invalid. Throws std::invalid_argument when the channels' counts or α planes disagree.
void UpdateAndAccumulateSurprise(const ChannelPlanes& planes, float* surprise, std::size_t n,
                                 const SurpriseBatchOptions& options);

/// One channel (see above).
void UpdateAndAccumulateSurprise(const float* x, ConstNormalGammaPlanes prior,
                                 NormalGammaPlanes posterior, float* surprise, std::size_t n,
                                 const SurpriseBatchOptions& options);

}  // namespace novelty::stats
