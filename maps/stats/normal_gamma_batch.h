// Per-pixel update + surprise over whole parameter planes: the inner loop of the appearance map.
//
// Planes are structure-of-arrays float buffers (one per hyperparameter), as the map stores them.
// Two kernels evaluate the same templates (UpdateWithForgetting, NormalGammaKL):
//   kScalar      one pixel at a time in double — the reference;
//   kVectorised  16 pixels at a time in float with Eigen fixed-size arrays (SIMD log/exp).
// Their results agree to float precision (normal_gamma_batch_test.cc).
#pragma once

#include <cstddef>

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

enum class BatchKernel { kScalar, kVectorised };

struct SurpriseBatchOptions {
  ForgettingUpdateOptions update;  ///< eq. 4.8-4.13 options
  NormalGammaKLOptions kl;         ///< eq. 4.15 options
  BatchKernel kernel = BatchKernel::kVectorised;
};

/// For each of n pixels i of one channel: posterior[i] = UpdateWithForgetting(prior[i], x[i]) and
/// surprise[i] += KL(posterior[i] ‖ prior[i]) — accumulation gives eq. 4.21 over channels.
/// A pixel whose observation x[i] is NaN (no data) keeps its prior as posterior and gets NaN
/// surprise, so it stays recognisably invalid. `posterior` may alias `prior`.
void UpdateAndAccumulateSurprise(const float* x, ConstNormalGammaPlanes prior,
                                 NormalGammaPlanes posterior, float* surprise, std::size_t n,
                                 const SurpriseBatchOptions& options);

}  // namespace novelty::stats
