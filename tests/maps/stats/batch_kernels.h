// Test helper: UpdateAndAccumulateSurprise by the library's vectorised kernel or by the
// double-precision reference (normal_gamma_pixel.h), chosen by KernelOptions::kernel. A call with
// KernelOptions picks these overloads; with SurpriseBatchOptions, the library's.
#pragma once

#include <cstddef>

#include "maps/stats/normal_gamma_batch.h"
#include "maps/stats/normal_gamma_pixel.h"

namespace novelty::stats {

enum class BatchKernel { kScalar, kVectorised };

struct KernelOptions : SurpriseBatchOptions {
  BatchKernel kernel = BatchKernel::kVectorised;
};

inline void UpdateAndAccumulateSurprise(const ChannelPlanes& planes, float* surprise,
                                        std::size_t n, const KernelOptions& options) {
  if (options.kernel == BatchKernel::kVectorised) {
    UpdateAndAccumulateSurprise(planes, surprise, n, SurpriseBatchOptions(options));
    return;
  }
  // No pixels: the library only checks the channels, as it does before its kernel.
  UpdateAndAccumulateSurprise(planes, surprise, 0, SurpriseBatchOptions(options));
  for (std::size_t i = 0; i < n; ++i) UpdateAndSurprisePixel<double>(i, planes, surprise, options);
}

inline void UpdateAndAccumulateSurprise(const float* x, ConstNormalGammaPlanes prior,
                                        NormalGammaPlanes posterior, float* surprise,
                                        std::size_t n, const KernelOptions& options) {
  UpdateAndAccumulateSurprise(ChannelPlanes{{x}, {prior}, {posterior}}, surprise, n, options);
}

}  // namespace novelty::stats
