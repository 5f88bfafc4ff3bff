// The SIMD kernel of the per-pixel update + surprise (normal_gamma_batch.h) on one thread:
// pixels [begin, end) of the planes, kPacketLanes at a time with Eigen's fixed-size arrays (SIMD
// log/exp) and core/lanes.h's masks, the tail one pixel at a time. UpdateAndAccumulateSurprise
// checks the channels and runs blocks of it on OpenCV's thread pool; this file needs neither
// OpenCV nor MRPT, so it is the file built and tested for every CPU target (scripts/portable.sh,
// scripts/cross_aarch64.sh) against the double-precision reference (normal_gamma_pixel.h).
#pragma once

#include <cstddef>

#include "maps/stats/normal_gamma_batch.h"

namespace novelty::stats {

/// Pixels per packet: two AVX-512 registers (four AVX2, eight NEON) per value. The kernel's
/// chains (exp, divisions, logarithms) are long, and two independent ones interleaved keep the
/// core busier than one, in spite of more register spills (docs/performance_history.md).
inline constexpr int kPacketLanes = 32;

/// UpdateAndAccumulateSurprise for pixels [begin, end) of checked planes (1 to kMaxChannels
/// channels sharing α), on the calling thread. Bit for bit the same as the batch's own blocks.
void UpdateAndAccumulateSurpriseRange(const ChannelPlanes& planes, float* surprise,
                                      std::size_t begin, std::size_t end,
                                      const SurpriseBatchOptions& options);

}  // namespace novelty::stats
