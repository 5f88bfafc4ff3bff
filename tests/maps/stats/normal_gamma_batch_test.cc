#include "maps/stats/normal_gamma_batch.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

#include "tests/maps/stats/batch_kernels.h"
#include "tests/maps/stats/random_planes.h"

namespace novelty::stats {
namespace {

TEST(NormalGammaBatch, ScalarKernelEqualsPerPixelFormulas) {
  const std::size_t n = 1001;
  const RandomPlanes prior(n, 5);
  RandomPlanes post(n, 6);
  std::vector<float> surprise(n, 1.0f);  // accumulates: starts at 1
  KernelOptions o;
  o.kernel = BatchKernel::kScalar;
  UpdateAndAccumulateSurprise(prior.x.data(), prior.View(), post.Mutable(), surprise.data(), n, o);
  for (std::size_t i = 0; i < n; i += 37) {
    const NormalGammaT<double> p0{prior.alpha[i], prior.beta[i], prior.tau[i], prior.sigma[i]};
    const auto p = UpdateWithForgetting<double>(p0, prior.x[i], o.update);
    EXPECT_FLOAT_EQ(post.alpha[i], float(p.alpha));
    EXPECT_FLOAT_EQ(post.beta[i], float(p.beta));
    EXPECT_FLOAT_EQ(post.tau[i], float(p.tau));
    EXPECT_FLOAT_EQ(post.sigma[i], float(p.sigma));
    EXPECT_FLOAT_EQ(surprise[i], float(1.0 + NormalGammaKL(p, p0)));
  }
}

// One channel's update and surprise from `prior` by the scalar and by the vectorised kernel.
struct BothKernels {
  RandomPlanes post_s, post_v;
  std::vector<float> s_scalar, s_vector;
  explicit BothKernels(const RandomPlanes& prior)
      : post_s(prior.x.size(), 1),
        post_v(prior.x.size(), 1),
        s_scalar(prior.x.size(), 0.0f),
        s_vector(prior.x.size(), 0.0f) {
    const std::size_t n = prior.x.size();
    KernelOptions o;
    o.kernel = BatchKernel::kScalar;
    UpdateAndAccumulateSurprise(prior.x.data(), prior.View(), post_s.Mutable(), s_scalar.data(), n,
                                o);
    o.kernel = BatchKernel::kVectorised;
    UpdateAndAccumulateSurprise(prior.x.data(), prior.View(), post_v.Mutable(), s_vector.data(), n,
                                o);
  }
};

TEST(NormalGammaBatch, VectorisedKernelAgreesWithScalarToFloatPrecision) {
  const std::size_t n = 320 * 240 + 7;  // a tail that is not a multiple of the packet size
  const RandomPlanes prior(n, 9);
  const BothKernels r(prior);
  const RandomPlanes &post_s = r.post_s, &post_v = r.post_v;
  const std::vector<float>&s_scalar = r.s_scalar, &s_vector = r.s_vector;
  double worst = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    EXPECT_NEAR(post_v.beta[i], post_s.beta[i], 2e-6f * post_s.beta[i]) << i;
    EXPECT_NEAR(post_v.tau[i], post_s.tau[i], 1e-4f) << i;
    EXPECT_NEAR(post_v.sigma[i], post_s.sigma[i], 2e-6f * post_s.sigma[i]) << i;
    const double err = std::abs(s_vector[i] - s_scalar[i]) / (1e-3 + s_scalar[i]);
    worst = std::max(worst, err);
  }
  EXPECT_LT(worst, 5e-4) << "worst relative surprise difference (absolute floor 1e-3)";
}

TEST(NormalGammaBatch, RunsOfEqualAlphaGiveTheSurpriseOfTheScalarKernel) {
  // α constant over runs of 40 pixels (crossing packet boundaries), in between runs of varying α,
  // and a run that comes back to an earlier value: the vectorised kernel reuses the α terms of the
  // previous packet only where all its α agree, and must still match the scalar reference.
  const std::size_t n = 1000;
  RandomPlanes prior(n, 11);
  const float runs[] = {2.5f, 1.25f, 2.5f, 0.8f};
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t run = i / 40;
    if (run % 2 == 0) prior.alpha[i] = runs[(run / 2) % 4];
  }
  const BothKernels r(prior);
  const RandomPlanes &post_s = r.post_s, &post_v = r.post_v;
  const std::vector<float>&s_scalar = r.s_scalar, &s_vector = r.s_vector;
  for (std::size_t i = 0; i < n; ++i) {
    ASSERT_NEAR(s_vector[i], s_scalar[i], 5e-4 * (1e-3 + s_scalar[i])) << i;
    ASSERT_FLOAT_EQ(post_v.alpha[i], post_s.alpha[i]) << i;
  }
}

TEST(NormalGammaBatch, NaNObservationKeepsPriorAndMarksSurpriseInvalid) {
  for (BatchKernel kernel : {BatchKernel::kScalar, BatchKernel::kVectorised}) {
    const std::size_t n = 40;
    RandomPlanes prior(n, 2);
    prior.x[3] = std::numeric_limits<float>::quiet_NaN();
    prior.x[21] = std::numeric_limits<float>::quiet_NaN();
    RandomPlanes post(n, 4);
    std::vector<float> surprise(n, 0.0f);
    KernelOptions o;
    o.kernel = kernel;
    UpdateAndAccumulateSurprise(prior.x.data(), prior.View(), post.Mutable(), surprise.data(), n,
                                o);
    for (std::size_t i : {3u, 21u}) {
      EXPECT_TRUE(std::isnan(surprise[i]));
      EXPECT_EQ(post.alpha[i], prior.alpha[i]);
      EXPECT_EQ(post.beta[i], prior.beta[i]);
      EXPECT_EQ(post.tau[i], prior.tau[i]);
      EXPECT_EQ(post.sigma[i], prior.sigma[i]);
    }
    EXPECT_TRUE(std::isfinite(surprise[4]));
    EXPECT_GT(surprise[4], 0.0f);
  }
}

TEST(NormalGammaBatch, InPlaceUpdateEqualsOutOfPlace) {
  const std::size_t n = 100;
  RandomPlanes in_place(n, 8);
  const RandomPlanes copy = in_place;
  RandomPlanes out(n, 1);
  std::vector<float> s1(n, 0.0f), s2(n, 0.0f);
  const SurpriseBatchOptions o;
  UpdateAndAccumulateSurprise(copy.x.data(), copy.View(), out.Mutable(), s1.data(), n, o);
  UpdateAndAccumulateSurprise(copy.x.data(), in_place.View(), in_place.Mutable(), s2.data(), n, o);
  EXPECT_EQ(in_place.tau, out.tau);
  EXPECT_EQ(in_place.beta, out.beta);
  EXPECT_EQ(s1, s2);
}

// Three channels sharing one α plane, in place, as the appearance map's tiles may use them: α
// uniform over whole packets (the KL's α terms cached from packet to packet), the second run's α
// the first run's posterior α, and a pixel without data. Each channel's prior is read before its
// posterior is written, and α's before all.
TEST(NormalGammaBatch, InPlaceChannelsSharingAlphaEqualOutOfPlace) {
  const std::size_t n = 160;
  const SurpriseBatchOptions o;
  float alpha_after_2 = 0.0f;  // the posterior α of α = 2, as the kernel computes it
  {
    RandomPlanes p(16, 3);
    std::fill(p.alpha.begin(), p.alpha.end(), 2.0f);
    std::vector<float> s(16, 0.0f);
    UpdateAndAccumulateSurprise(p.x.data(), p.View(), p.Mutable(), s.data(), 16, o);
    alpha_after_2 = p.alpha[0];
  }
  ASSERT_NEAR(alpha_after_2, 2.1f, 1e-6f);  // 0.8 · 2 + 0.5
  std::vector<RandomPlanes> in_place;
  for (unsigned k = 0; k < 3; ++k) in_place.emplace_back(n, 40 + k);
  for (std::size_t i = 0; i < n; ++i)
    in_place[0].alpha[i] = i < 32 ? 2.0f : i < 96 ? alpha_after_2 : 1.25f;
  for (unsigned k = 1; k < 3; ++k) in_place[k].alpha = in_place[0].alpha;
  in_place[2].x[70] = std::numeric_limits<float>::quiet_NaN();
  const std::vector<RandomPlanes> copy = in_place;
  std::vector<RandomPlanes> out(3, RandomPlanes(n, 1));
  ChannelPlanes separate, shared;
  for (unsigned k = 0; k < 3; ++k) {
    separate.x.push_back(copy[k].x.data());
    separate.prior.push_back(
        {copy[0].alpha.data(), copy[k].beta.data(), copy[k].tau.data(), copy[k].sigma.data()});
    separate.posterior.push_back(
        {out[0].alpha.data(), out[k].beta.data(), out[k].tau.data(), out[k].sigma.data()});
    shared.x.push_back(copy[k].x.data());
    shared.prior.push_back({in_place[0].alpha.data(), in_place[k].beta.data(),
                            in_place[k].tau.data(), in_place[k].sigma.data()});
    shared.posterior.push_back({in_place[0].alpha.data(), in_place[k].beta.data(),
                                in_place[k].tau.data(), in_place[k].sigma.data()});
  }
  std::vector<float> s1(n, 0.0f), s2(n, 0.0f);
  UpdateAndAccumulateSurprise(separate, s1.data(), n, o);
  UpdateAndAccumulateSurprise(shared, s2.data(), n, o);
  EXPECT_EQ(in_place[0].alpha, out[0].alpha);
  for (unsigned k = 0; k < 3; ++k) {
    EXPECT_EQ(in_place[k].beta, out[k].beta) << k;
    EXPECT_EQ(in_place[k].tau, out[k].tau) << k;
    EXPECT_EQ(in_place[k].sigma, out[k].sigma) << k;
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (i == 70) {
      EXPECT_TRUE(std::isnan(s2[i]));
    } else {
      EXPECT_EQ(s1[i], s2[i]) << i;
    }
  }
  EXPECT_NE(copy[0].alpha, in_place[0].alpha);  // it was updated
}

TEST(NormalGammaBatch, ChannelsSharingAlphaEqualSeparateChannels) {
  // Three channels with one α plane against three single-channel calls on copies of α: the same
  // posteriors, and the same summed surprise — eq. 4.21 sums whole KLs, α terms included, so
  // sharing the α plane must not change the sum.
  const std::size_t n = 517;  // not a multiple of 16: the tail runs the scalar code
  for (BatchKernel kernel : {BatchKernel::kScalar, BatchKernel::kVectorised}) {
    KernelOptions o;
    o.kernel = kernel;
    std::vector<RandomPlanes> prior, separate;
    for (unsigned k = 0; k < 3; ++k) prior.emplace_back(n, 20 + k);
    for (unsigned k = 1; k < 3; ++k) prior[k].alpha = prior[0].alpha;
    prior[1].x[7] = std::numeric_limits<float>::quiet_NaN();  // one channel without data
    separate = prior;
    std::vector<float> shared_surprise(n, 0.0f), separate_surprise(n, 0.0f);
    std::vector<RandomPlanes> shared = prior;
    ChannelPlanes c;
    for (int k = 0; k < 3; ++k) {
      c.x.push_back(prior[k].x.data());
      c.prior.push_back(prior[k].View());
      c.prior.back().alpha = prior[0].alpha.data();
      c.posterior.push_back(shared[k].Mutable());
      c.posterior.back().alpha = shared[0].alpha.data();
    }
    UpdateAndAccumulateSurprise(c, shared_surprise.data(), n, o);
    for (int k = 0; k < 3; ++k) {
      UpdateAndAccumulateSurprise(prior[k].x.data(), prior[k].View(), separate[k].Mutable(),
                                  separate_surprise.data(), n, o);
    }
    for (std::size_t i = 0; i < n; ++i) {
      if (i == 7) {
        EXPECT_TRUE(std::isnan(shared_surprise[i]));
        EXPECT_EQ(shared[0].alpha[i], prior[0].alpha[i]);  // the prior kept in every channel
        EXPECT_EQ(shared[2].tau[i], prior[2].tau[i]);
        continue;
      }
      ASSERT_NEAR(shared_surprise[i], separate_surprise[i], 1e-4 * (1.0 + separate_surprise[i]))
          << i;
      for (int k = 0; k < 3; ++k) {
        ASSERT_EQ(shared[0].alpha[i], separate[k].alpha[i]) << i;
        ASSERT_FLOAT_EQ(shared[k].beta[i], separate[k].beta[i]) << i;
        ASSERT_FLOAT_EQ(shared[k].tau[i], separate[k].tau[i]) << i;
        ASSERT_FLOAT_EQ(shared[k].sigma[i], separate[k].sigma[i]) << i;
      }
    }
  }
}

// Channels `in` (observation, prior) updated into `out`, all sharing channel 0's α plane.
ChannelPlanes SharedAlphaChannels(const std::vector<RandomPlanes>& in,
                                  std::vector<RandomPlanes>& out) {
  ChannelPlanes planes;
  for (std::size_t k = 0; k < in.size(); ++k) {
    planes.x.push_back(in[k].x.data());
    planes.prior.push_back(
        {in[0].alpha.data(), in[k].beta.data(), in[k].tau.data(), in[k].sigma.data()});
    planes.posterior.push_back(
        {out[0].alpha.data(), out[k].beta.data(), out[k].tau.data(), out[k].sigma.data()});
  }
  return planes;
}

// The states a map's pixels are in, three channels (Y, Cb, Cr) sharing α, with the observation
// that arrives: a pixel's first ten updates from the initial prior (1, 1, 0, 5); α0 < 1 (an
// initial prior set lower); blends of two or three views of different ages (the blend averages
// each parameter, α included); and generic states.
struct ThreeChannelStates {
  std::vector<RandomPlanes> c;  // per channel
  explicit ThreeChannelStates(std::size_t n) {
    for (unsigned k = 0; k < 3; ++k) c.emplace_back(n, 70 + k);
    std::mt19937 rng(77);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    std::normal_distribution<double> noise(0.0, 2.0);
    const ForgettingUpdateOptions f;
    // `ages` updates of one pixel from the initial prior with noisy samples around `level`.
    const auto aged = [&](int ages, double level) {
      NormalGamma p = InitialPrior();
      for (int a = 0; a < ages; ++a) p = UpdateWithForgetting(p, level + noise(rng), f);
      return p;
    };
    for (std::size_t i = 0; i < n; ++i) {
      const int kind = int(i % 4);
      NormalGamma p[3];
      for (int k = 0; k < 3; ++k) {
        const double level = 20.0 + 200.0 * u(rng);
        if (kind == 0) {  // the first ten updates
          p[k] = aged(int((i / 4) % 10), level);
        } else if (kind == 1) {  // α0 < 1
          p[k] = {0.2 + 0.79 * u(rng), std::exp(-3.0 + 7.0 * u(rng)), level,
                  std::exp(-4.0 + 5.6 * u(rng))};
        } else if (kind == 2) {  // a blend of views of different ages
          const int views = 2 + int(i / 4) % 2;
          p[k] = {0, 0, 0, 0};
          for (int v = 0; v < views; ++v) {
            const NormalGamma a = aged(1 + int(u(rng) * 30.0), level + 5.0 * u(rng));
            p[k].alpha += a.alpha / views;
            p[k].beta += a.beta / views;
            p[k].tau += a.tau / views;
            p[k].sigma += a.sigma / views;
          }
        } else {  // generic: whatever RandomPlanes drew
          p[k] = {c[0].alpha[i], c[k].beta[i], c[k].tau[i], c[k].sigma[i]};
        }
      }
      for (int k = 0; k < 3; ++k) {
        c[k].alpha[i] = float(p[0].alpha);  // shared α: channel 0's
        c[k].beta[i] = float(p[k].beta);
        c[k].tau[i] = float(p[k].tau);
        c[k].sigma[i] = float(p[k].sigma);
        // Mostly noise, sometimes a change.
        const double step = u(rng) < 0.8 ? noise(rng) : 120.0 * (u(rng) - 0.5);
        c[k].x[i] = float(std::clamp(p[k].tau + step, 0.0, 255.0));
      }
    }
  }
  // S = Σ_k KL_k (eq. 4.21) in double, each channel's update and KL on its own.
  double Reference(std::size_t i, const ForgettingUpdateOptions& f) const {
    double sum = 0.0;
    for (int k = 0; k < 3; ++k) {
      const NormalGamma p0{c[0].alpha[i], c[k].beta[i], c[k].tau[i], c[k].sigma[i]};
      sum += NormalGammaKL(UpdateWithForgetting(p0, double(c[k].x[i]), f), p0);
    }
    return sum;
  }
};

// eq. 4.21 against three double-precision KLs, for both kernels, over 120 000 pixel states: the
// relative error is at most 1e-4 (below S = 0.01 — a pixel nobody would look at — at most 1e-6
// absolute, float's resolution of the posterior there), and S is never negative.
TEST(NormalGammaBatch, ThreeChannelSurpriseIsTheSumOfTheChannelsKL) {
  const std::size_t n = 120000;
  const ThreeChannelStates states(n);
  for (BatchKernel kernel : {BatchKernel::kScalar, BatchKernel::kVectorised}) {
    KernelOptions o;
    o.kernel = kernel;
    std::vector<RandomPlanes> out(3, RandomPlanes(n, 1));
    std::vector<float> surprise(n, 0.0f);
    UpdateAndAccumulateSurprise(SharedAlphaChannels(states.c, out), surprise.data(), n, o);
    double worst = 0.0;
    std::size_t worst_at = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const double truth = states.Reference(i, o.update);
      ASSERT_GE(surprise[i], 0.0f) << i;
      const double err = std::abs(surprise[i] - truth) / std::max(truth, 0.01);
      if (err > worst) {
        worst = err;
        worst_at = i;
      }
    }
    EXPECT_LE(worst, 1e-4) << (kernel == BatchKernel::kScalar ? "scalar" : "vectorised")
                           << " kernel, worst at pixel " << worst_at
                           << ": S = " << surprise[worst_at] << ", eq. 4.21 "
                           << states.Reference(worst_at, o.update);
  }
}

// (α0 = 1, β0 = 0.5, σ0 = 0.01) in three channels, each stepping by 0.7: eq. 4.21 gives +0.0743
// (the α terms counted once for three channels gave −0.0405, a negative KL).
TEST(NormalGammaBatch, KnownThreeChannelCase) {
  for (BatchKernel kernel : {BatchKernel::kScalar, BatchKernel::kVectorised}) {
    const std::size_t n = 64;
    std::vector<RandomPlanes> c(3, RandomPlanes(n, 1)), out(3, RandomPlanes(n, 2));
    for (int k = 0; k < 3; ++k) {
      std::fill(c[k].alpha.begin(), c[k].alpha.end(), 1.0f);
      std::fill(c[k].beta.begin(), c[k].beta.end(), 0.5f);
      std::fill(c[k].tau.begin(), c[k].tau.end(), 100.0f);
      std::fill(c[k].sigma.begin(), c[k].sigma.end(), 0.01f);
      std::fill(c[k].x.begin(), c[k].x.end(), 100.7f);
    }
    const ChannelPlanes planes = SharedAlphaChannels(c, out);
    KernelOptions o;
    o.kernel = kernel;
    std::vector<float> s(n, 0.0f);
    UpdateAndAccumulateSurprise(planes, s.data(), n, o);
    // The independent value: eq. 4.16-4.20 as printed, per channel, summed (eq. 4.21).
    double truth = 0.0;
    for (int k = 0; k < 3; ++k) {
      const NormalGamma p0{1.0, 0.5, 100.0, 0.01};
      truth += NormalGammaKLAsPrinted(UpdateWithForgetting(p0, 100.7, o.update), p0);
    }
    EXPECT_NEAR(truth, 0.0743, 5e-4);
    EXPECT_NEAR(s[0], truth, 1e-4 * truth);
    EXPECT_NEAR(s[n - 1], truth, 1e-4 * truth);
  }
}

// A prior gone bad (β = 0: no precision) gives NaN surprise, never a silent 0 from the clamp that
// keeps rounding from making a KL negative.
TEST(NormalGammaBatch, ABadPriorGivesNaNNotZero) {
  for (BatchKernel kernel : {BatchKernel::kScalar, BatchKernel::kVectorised}) {
    const std::size_t n = 40;
    RandomPlanes prior(n, 3);
    std::fill(prior.beta.begin(), prior.beta.end(), 0.0f);
    std::fill(prior.sigma.begin(), prior.sigma.end(), 0.0f);
    prior.x = prior.tau;  // the same value: 0/0 in the KL's β and σ terms
    RandomPlanes post(n, 4);
    std::vector<float> surprise(n, 0.0f);
    KernelOptions o;
    o.kernel = kernel;
    o.update.min_variance = 0.0;  // the thesis's update: nothing lifts β
    o.update.sigma_min = 1e-30;
    UpdateAndAccumulateSurprise(prior.x.data(), prior.View(), post.Mutable(), surprise.data(), n,
                                o);
    for (std::size_t i = 0; i < n; ++i) EXPECT_TRUE(std::isnan(surprise[i])) << i;
  }
}

TEST(NormalGammaBatch, ChannelsMustShareAlpha) {
  RandomPlanes a(16, 1), b(16, 2);
  std::vector<float> surprise(16, 0.0f);
  ChannelPlanes c{{a.x.data(), b.x.data()}, {a.View(), b.View()}, {a.Mutable(), b.Mutable()}};
  EXPECT_THROW(UpdateAndAccumulateSurprise(c, surprise.data(), 16, SurpriseBatchOptions{}),
               std::invalid_argument);
  c.posterior.pop_back();
  EXPECT_THROW(UpdateAndAccumulateSurprise(c, surprise.data(), 16, SurpriseBatchOptions{}),
               std::invalid_argument);
}

}  // namespace
}  // namespace novelty::stats
