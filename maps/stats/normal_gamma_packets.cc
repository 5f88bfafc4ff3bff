#include "maps/stats/normal_gamma_packets.h"

#include <cmath>
#include <limits>

#include "core/lanes.h"
#include "core/with_count.h"
#include "maps/stats/normal_gamma_pixel.h"

namespace novelty::stats {

namespace {

constexpr int kLanes = kPacketLanes;
using Packet = Eigen::Array<float, kLanes, 1>;
using PacketMap = Eigen::Map<Packet, Eigen::Unaligned>;
using ConstPacketMap = Eigen::Map<const Packet, Eigen::Unaligned>;

// The KL's α terms depend on the prior α alone (the update of α does not see the data,
// eq. 4.10), and whole frames share one α where every pixel was updated alike: the last packet's
// terms serve the next when its α all agree with them — computed the same way, so the
// surprise is the same to the bit. `terms` holds them summed over the channels (eq. 4.21).
struct AlphaTermsCache {
  float prior_alpha = -1.0f;  // no α is negative: nothing cached yet
  Packet terms;
};

// kLanes pixels of `channels` channels in float. Every prior is read before any posterior is
// written (in-place use). Flattened, and the channel count known to the compiler: GCC otherwise
// calls the update and KL templates and keeps the per-channel packets in memory.
template <int channels>
__attribute__((flatten)) void ProcessPacket(std::size_t i, const ChannelPlanes& c, float* surprise,
                                            const SurpriseBatchOptions& o, AlphaTermsCache& cache) {
  // Lane tests with vector extensions: Eigen compares boolean arrays lane by lane.
  namespace L = core::lanes;
  constexpr int kParts = kLanes / L::kLanes;
  // Whether every lane of `values(part)` equals `to(part)`, part by part.
  const auto all_equal = [](auto values, auto to) {
    bool all = true;
    for (int h = 0; h < kParts; ++h) all = all && L::All(values(h) == to(h));
    return all;
  };
  Packet x[kMaxChannels];
  L::I16 valid_lanes[kParts];
  for (L::I16& v : valid_lanes) v = L::I16{} == 0;
  for (int k = 0; k < channels; ++k) {
    x[k] = ConstPacketMap(c.x[k] + i);
    for (int h = 0; h < kParts; ++h) {
      const L::F16 v = L::Load(c.x[k] + i + h * L::kLanes);
      valid_lanes[h] &= v == v;  // false for NaN
    }
  }
  // The usual packet without NaN skips the selects (Eigen evaluates them lane by lane too).
  const bool all_valid =
      all_equal([&](int h) { return valid_lanes[h]; }, [](int) { return L::I16{} - 1; });
  Eigen::Array<bool, kLanes, 1> valid;
  if (!all_valid)
    for (int l = 0; l < kLanes; ++l) valid(l) = valid_lanes[l / L::kLanes][l % L::kLanes] != 0;
  NormalGammaT<Packet> p0[kMaxChannels], p[kMaxChannels];
  Packet shift[kMaxChannels];
  const Packet alpha0 = ConstPacketMap(c.prior[0].alpha + i), inv_alpha0 = alpha0.inverse();
  for (int k = 0; k < channels; ++k) {
    const ConstNormalGammaPlanes& q = c.prior[std::size_t(k)];
    p0[k] = {alpha0, ConstPacketMap(q.beta + i), ConstPacketMap(q.tau + i),
             ConstPacketMap(q.sigma + i)};
    // Invalid lanes are computed on the prior's own τ (harmless numbers) and masked afterwards.
    if (!all_valid) x[k] = valid.select(x[k], p0[k].tau).eval();
    p[k] = UpdateWithSigma(p0[k], x[k], o.update, AdaptiveSigma(p0[k], o.update, inv_alpha0),
                           &shift[k]);
  }
  Packet kl = NormalGammaKLOtherTerms(p, p0, shift, channels);
  const float* a0 = c.prior[0].alpha + i;
  const auto a0_part = [&](int h) { return L::Load(a0 + h * L::kLanes); };
  if (all_equal(a0_part, [&](int) { return L::F16{} + cache.prior_alpha; })) {
    kl += cache.terms;
  } else {
    // eq. 4.21: each channel's KL holds the α terms once, though the channels share α.
    const Packet terms = float(channels) * NormalGammaKLAlphaTerms(p[0].alpha, p0[0].alpha, o.kl);
    kl += terms;
    const float first = a0[0];
    if (all_equal(a0_part, [&](int) { return L::F16{} + first; })) cache = {first, terms};
  }
  // KL ≥ 0 (Gibbs); float rounding of a near-zero sum must not make it negative. A NaN (a state
  // gone bad) stays NaN: max() would turn it into a silent 0.
  kl = (kl < 0.0f).select(Packet::Zero(), kl);
  PacketMap s(surprise + i);
  for (int k = 0; k < channels; ++k) {
    const NormalGammaPlanes& q = c.posterior[std::size_t(k)];
    if (all_valid) {
      PacketMap(q.alpha + i) = p[k].alpha;
      PacketMap(q.beta + i) = p[k].beta;
      PacketMap(q.tau + i) = p[k].tau;
      PacketMap(q.sigma + i) = p[k].sigma;
    } else {
      PacketMap(q.alpha + i) = valid.select(p[k].alpha, p0[k].alpha);
      PacketMap(q.beta + i) = valid.select(p[k].beta, p0[k].beta);
      PacketMap(q.tau + i) = valid.select(p[k].tau, p0[k].tau);
      PacketMap(q.sigma + i) = valid.select(p[k].sigma, p0[k].sigma);
    }
  }
  if (all_valid) {
    s += kl;
  } else {
    s = valid.select(s + kl, Packet::Constant(std::numeric_limits<float>::quiet_NaN()));
  }
}

// ProcessPacket compiled for each channel count (1 to kMaxChannels).
auto PacketKernelFor(int channels) {
  static_assert(kMaxChannels == 4);
  return core::WithCount<4, 1, 2, 3>(channels,
                                     [](auto n) { return &ProcessPacket<decltype(n)::value>; });
}

}  // namespace

void UpdateAndAccumulateSurpriseRange(const ChannelPlanes& planes, float* surprise,
                                      std::size_t begin, std::size_t end,
                                      const SurpriseBatchOptions& options) {
  const auto packet = PacketKernelFor(int(planes.x.size()));
  AlphaTermsCache cache;
  std::size_t i = begin;
  for (; i + kPacketLanes <= end; i += kPacketLanes) packet(i, planes, surprise, options, cache);
  for (; i < end; ++i) UpdateAndSurprisePixel<float>(i, planes, surprise, options);  // the tail
}

}  // namespace novelty::stats
