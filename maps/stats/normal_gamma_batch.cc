#include "maps/stats/normal_gamma_batch.h"

#include <cmath>
#include <limits>

namespace novelty::stats {

namespace {

constexpr int kLanes = 16;
using Packet = Eigen::Array<float, kLanes, 1>;
using PacketMap = Eigen::Map<Packet, Eigen::Unaligned>;
using ConstPacketMap = Eigen::Map<const Packet, Eigen::Unaligned>;

template <class T>
void ProcessOne(std::size_t i, const float* x, ConstNormalGammaPlanes prior,
                NormalGammaPlanes posterior, float* surprise, const SurpriseBatchOptions& o) {
  const NormalGammaT<T> p0{T(prior.alpha[i]), T(prior.beta[i]), T(prior.tau[i]), T(prior.sigma[i])};
  if (std::isnan(x[i])) {
    posterior.alpha[i] = prior.alpha[i];
    posterior.beta[i] = prior.beta[i];
    posterior.tau[i] = prior.tau[i];
    posterior.sigma[i] = prior.sigma[i];
    surprise[i] = std::numeric_limits<float>::quiet_NaN();
    return;
  }
  T shift;
  const NormalGammaT<T> p = UpdateWithForgetting(p0, T(x[i]), o.update, &shift);
  const T kl = NormalGammaKLWithShift(p, p0, shift, o.kl);
  posterior.alpha[i] = static_cast<float>(p.alpha);
  posterior.beta[i] = static_cast<float>(p.beta);
  posterior.tau[i] = static_cast<float>(p.tau);
  posterior.sigma[i] = static_cast<float>(p.sigma);
  surprise[i] += static_cast<float>(kl);
}

void ProcessPacket(std::size_t i, const float* x, ConstNormalGammaPlanes prior,
                   NormalGammaPlanes posterior, float* surprise, const SurpriseBatchOptions& o) {
  const NormalGammaT<Packet> p0{ConstPacketMap(prior.alpha + i), ConstPacketMap(prior.beta + i),
                                ConstPacketMap(prior.tau + i), ConstPacketMap(prior.sigma + i)};
  const Packet xi = ConstPacketMap(x + i);
  const auto valid = (xi == xi);  // false for NaN
  // Invalid lanes are computed on the prior's own τ (harmless numbers) and masked afterwards.
  const Packet x_safe = valid.select(xi, p0.tau);
  Packet shift;
  const NormalGammaT<Packet> p = UpdateWithForgetting(p0, x_safe, o.update, &shift);
  const Packet kl = NormalGammaKLWithShift(p, p0, shift, o.kl);
  PacketMap(posterior.alpha + i) = valid.select(p.alpha, p0.alpha);
  PacketMap(posterior.beta + i) = valid.select(p.beta, p0.beta);
  PacketMap(posterior.tau + i) = valid.select(p.tau, p0.tau);
  PacketMap(posterior.sigma + i) = valid.select(p.sigma, p0.sigma);
  PacketMap s(surprise + i);
  s = valid.select(s + kl, Packet::Constant(std::numeric_limits<float>::quiet_NaN()));
}

}  // namespace

void UpdateAndAccumulateSurprise(const float* x, ConstNormalGammaPlanes prior,
                                 NormalGammaPlanes posterior, float* surprise, std::size_t n,
                                 const SurpriseBatchOptions& options) {
  std::size_t i = 0;
  if (options.kernel == BatchKernel::kVectorised) {
    for (; i + kLanes <= n; i += kLanes) ProcessPacket(i, x, prior, posterior, surprise, options);
    for (; i < n; ++i) ProcessOne<float>(i, x, prior, posterior, surprise, options);
    return;
  }
  for (; i < n; ++i) ProcessOne<double>(i, x, prior, posterior, surprise, options);
}

}  // namespace novelty::stats
