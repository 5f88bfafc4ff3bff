#include "maps/stats/normal_gamma_packets.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "maps/stats/normal_gamma_pixel.h"
#include "tests/maps/stats/random_planes.h"

namespace novelty::stats {
namespace {

// 1 to 4 channels sharing channel 0's α plane, n pixels, NaN observations at `nan_pixels` of
// channel 1 (or 0), and the surprise accumulated into `surprise` — by the packet kernel or, in
// double precision one pixel at a time, by the reference (normal_gamma_pixel.h).
struct Run {
  std::vector<RandomPlanes> prior, post;
  std::vector<float> surprise;
  Run(int channels, std::size_t n, const std::vector<std::size_t>& nan_pixels, bool reference,
      const std::vector<float>* alpha = nullptr) {
    for (int k = 0; k < channels; ++k) prior.emplace_back(n, 30u + unsigned(k));
    if (alpha) prior[0].alpha = *alpha;
    for (std::size_t i : nan_pixels)
      prior[std::size_t(channels > 1)].x[i] = std::numeric_limits<float>::quiet_NaN();
    post = prior;
    surprise.assign(n, 0.5f);  // accumulates
    ChannelPlanes c;
    for (int k = 0; k < channels; ++k) {
      c.x.push_back(prior[std::size_t(k)].x.data());
      c.prior.push_back(prior[std::size_t(k)].View());
      c.prior.back().alpha = prior[0].alpha.data();
      c.posterior.push_back(post[std::size_t(k)].Mutable());
      c.posterior.back().alpha = post[0].alpha.data();
    }
    const SurpriseBatchOptions o;
    if (reference) {
      for (std::size_t i = 0; i < n; ++i) UpdateAndSurprisePixel<double>(i, c, surprise.data(), o);
    } else {
      UpdateAndAccumulateSurpriseRange(c, surprise.data(), 0, n, o);
    }
  }
};

// The kernel against the double-precision reference, to the batch tests' float tolerances
// (normal_gamma_batch_test.cc): every channel count, whole packets and a tail, NaN pixels.
void ExpectAgreement(int channels, const std::vector<float>* alpha = nullptr) {
  const std::size_t n = 40 * kPacketLanes + 13;
  const std::vector<std::size_t> nan_pixels = {3, 70, n - 2};
  const Run kernel(channels, n, nan_pixels, false, alpha),
      ref(channels, n, nan_pixels, true, alpha);
  double worst = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const bool nan = i == 3 || i == 70 || i == n - 2;
    if (nan) {
      ASSERT_TRUE(std::isnan(kernel.surprise[i])) << i;
      for (int k = 0; k < channels; ++k) ASSERT_EQ(kernel.post[k].tau[i], kernel.prior[k].tau[i]);
      ASSERT_EQ(kernel.post[0].alpha[i], kernel.prior[0].alpha[i]) << i;
      continue;
    }
    ASSERT_FLOAT_EQ(kernel.post[0].alpha[i], ref.post[0].alpha[i]) << i;
    for (int k = 0; k < channels; ++k) {
      const RandomPlanes &v = kernel.post[std::size_t(k)], &s = ref.post[std::size_t(k)];
      ASSERT_NEAR(v.beta[i], s.beta[i], 2e-6f * s.beta[i]) << i;
      ASSERT_NEAR(v.tau[i], s.tau[i], 1e-4f) << i;
      ASSERT_NEAR(v.sigma[i], s.sigma[i], 2e-6f * s.sigma[i]) << i;
    }
    const double err = std::abs(kernel.surprise[i] - ref.surprise[i]) / (1e-3 + ref.surprise[i]);
    worst = std::max(worst, err);
  }
  EXPECT_LT(worst, 5e-4) << channels << " channels: worst relative surprise difference";
}

TEST(NormalGammaPackets, AgreeWithTheDoublePrecisionReference) {
  for (int channels = 1; channels <= kMaxChannels; ++channels) ExpectAgreement(channels);
}

TEST(NormalGammaPackets, RunsOfEqualAlphaAgreeWithTheReference) {
  // α constant over runs of 40 pixels (across packet boundaries) between runs of varying α: the
  // kernel reuses a packet's α terms for the next only where all its α agree.
  std::vector<float> alpha = RandomPlanes(40 * kPacketLanes + 13, 30).alpha;
  const float runs[] = {2.5f, 1.25f, 2.5f, 0.8f};
  for (std::size_t i = 0; i < alpha.size(); ++i)
    if ((i / 40) % 2 == 0) alpha[i] = runs[(i / 80) % 4];
  ExpectAgreement(3, &alpha);
}

TEST(NormalGammaPackets, ARangeSplitAtAPacketGivesTheSameBits) {
  // The batch runs blocks of whole packets on separate threads: its result must not depend on
  // where the blocks start.
  const std::size_t n = 10 * kPacketLanes + 5;
  const RandomPlanes prior(n, 3);
  RandomPlanes whole = prior, split = prior;
  std::vector<float> s_whole(n, 0.0f), s_split(n, 0.0f);
  const SurpriseBatchOptions o;
  const ChannelPlanes a{{prior.x.data()}, {prior.View()}, {whole.Mutable()}};
  const ChannelPlanes b{{prior.x.data()}, {prior.View()}, {split.Mutable()}};
  UpdateAndAccumulateSurpriseRange(a, s_whole.data(), 0, n, o);
  UpdateAndAccumulateSurpriseRange(b, s_split.data(), 0, 4 * kPacketLanes, o);
  UpdateAndAccumulateSurpriseRange(b, s_split.data(), 4 * kPacketLanes, n, o);
  EXPECT_EQ(s_whole, s_split);
  EXPECT_EQ(whole.beta, split.beta);
  EXPECT_EQ(whole.tau, split.tau);
  EXPECT_EQ(whole.sigma, split.sigma);
}

}  // namespace
}  // namespace novelty::stats
