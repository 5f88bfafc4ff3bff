#include "maps/stats/normal_gamma_batch.h"

#include <algorithm>
#include <opencv2/core/utility.hpp>
#include <stdexcept>
#include <string>

#include "maps/stats/normal_gamma_packets.h"

namespace novelty::stats {

namespace {

// Packets per parallel block: enough work per task to hide the thread pool's overhead.
constexpr std::size_t kPacketsPerBlock = 256;

void CheckChannels(const ChannelPlanes& c) {
  const std::size_t n = c.x.size();
  if (n == 0 || n > std::size_t(kMaxChannels) || c.prior.size() != n || c.posterior.size() != n) {
    throw std::invalid_argument(
        "UpdateAndAccumulateSurprise: need 1 to " + std::to_string(kMaxChannels) +
        " channels with one prior and posterior each, got " + std::to_string(n) + "/" +
        std::to_string(c.prior.size()) + "/" + std::to_string(c.posterior.size()));
  }
  for (std::size_t k = 1; k < n; ++k) {
    if (c.prior[k].alpha != c.prior[0].alpha || c.posterior[k].alpha != c.posterior[0].alpha) {
      throw std::invalid_argument("UpdateAndAccumulateSurprise: channel " + std::to_string(k) +
                                  " does not share channel 0's alpha plane");
    }
  }
}

}  // namespace

void UpdateAndAccumulateSurprise(const ChannelPlanes& planes, float* surprise, std::size_t n,
                                 const SurpriseBatchOptions& options) {
  CheckChannels(planes);
  // Pixels are independent: blocks of whole packets go to OpenCV's thread pool.
  const std::size_t block = kPacketsPerBlock * kPacketLanes;
  const int blocks = int((n + block - 1) / block);
  cv::parallel_for_(cv::Range(0, blocks), [&](const cv::Range& r) {
    UpdateAndAccumulateSurpriseRange(planes, surprise, std::size_t(r.start) * block,
                                     std::min(n, std::size_t(r.end) * block), options);
  });
}

void UpdateAndAccumulateSurprise(const float* x, ConstNormalGammaPlanes prior,
                                 NormalGammaPlanes posterior, float* surprise, std::size_t n,
                                 const SurpriseBatchOptions& options) {
  UpdateAndAccumulateSurprise(ChannelPlanes{{x}, {prior}, {posterior}}, surprise, n, options);
}

}  // namespace novelty::stats
