#include "maps/stats/normal_gamma_batch.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

namespace novelty::stats {
namespace {

// A plane set of n pixels with plausible map parameters and observations.
struct Planes {
  std::vector<float> alpha, beta, tau, sigma, x;
  explicit Planes(std::size_t n, unsigned seed) : alpha(n), beta(n), tau(n), sigma(n), x(n) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> a(0.6f, 3.0f), lb(-2.0f, 8.0f), t(0.0f, 255.0f),
        ls(-4.0f, 1.6f), dx(-80.0f, 80.0f);
    for (std::size_t i = 0; i < n; ++i) {
      alpha[i] = a(rng);
      beta[i] = std::exp(lb(rng));
      tau[i] = t(rng);
      sigma[i] = std::exp(ls(rng));
      x[i] = tau[i] + (i % 3 == 0 ? dx(rng) * 0.05f : dx(rng));
    }
  }
  ConstNormalGammaPlanes View() const {
    return {alpha.data(), beta.data(), tau.data(), sigma.data()};
  }
  NormalGammaPlanes Mutable() { return {alpha.data(), beta.data(), tau.data(), sigma.data()}; }
};

TEST(NormalGammaBatch, ScalarKernelEqualsPerPixelFormulas) {
  const std::size_t n = 1001;
  const Planes prior(n, 5);
  Planes post(n, 6);
  std::vector<float> surprise(n, 1.0f);  // accumulates: starts at 1
  SurpriseBatchOptions o;
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
  Planes post_s, post_v;
  std::vector<float> s_scalar, s_vector;
  explicit BothKernels(const Planes& prior)
      : post_s(prior.x.size(), 1),
        post_v(prior.x.size(), 1),
        s_scalar(prior.x.size(), 0.0f),
        s_vector(prior.x.size(), 0.0f) {
    const std::size_t n = prior.x.size();
    SurpriseBatchOptions o;
    o.kernel = BatchKernel::kScalar;
    UpdateAndAccumulateSurprise(prior.x.data(), prior.View(), post_s.Mutable(), s_scalar.data(),
                                n, o);
    o.kernel = BatchKernel::kVectorised;
    UpdateAndAccumulateSurprise(prior.x.data(), prior.View(), post_v.Mutable(), s_vector.data(),
                                n, o);
  }
};

TEST(NormalGammaBatch, VectorisedKernelAgreesWithScalarToFloatPrecision) {
  const std::size_t n = 320 * 240 + 7;  // a tail that is not a multiple of the packet size
  const Planes prior(n, 9);
  const BothKernels r(prior);
  const Planes &post_s = r.post_s, &post_v = r.post_v;
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
  Planes prior(n, 11);
  const float runs[] = {2.5f, 1.25f, 2.5f, 0.8f};
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t run = i / 40;
    if (run % 2 == 0) prior.alpha[i] = runs[(run / 2) % 4];
  }
  const BothKernels r(prior);
  const Planes &post_s = r.post_s, &post_v = r.post_v;
  const std::vector<float>&s_scalar = r.s_scalar, &s_vector = r.s_vector;
  for (std::size_t i = 0; i < n; ++i) {
    ASSERT_NEAR(s_vector[i], s_scalar[i], 5e-4 * (1e-3 + s_scalar[i])) << i;
    ASSERT_FLOAT_EQ(post_v.alpha[i], post_s.alpha[i]) << i;
  }
}

TEST(NormalGammaBatch, NaNObservationKeepsPriorAndMarksSurpriseInvalid) {
  for (BatchKernel kernel : {BatchKernel::kScalar, BatchKernel::kVectorised}) {
    const std::size_t n = 40;
    Planes prior(n, 2);
    prior.x[3] = std::numeric_limits<float>::quiet_NaN();
    prior.x[21] = std::numeric_limits<float>::quiet_NaN();
    Planes post(n, 4);
    std::vector<float> surprise(n, 0.0f);
    SurpriseBatchOptions o;
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
  Planes in_place(n, 8);
  const Planes copy = in_place;
  Planes out(n, 1);
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
    Planes p(16, 3);
    std::fill(p.alpha.begin(), p.alpha.end(), 2.0f);
    std::vector<float> s(16, 0.0f);
    UpdateAndAccumulateSurprise(p.x.data(), p.View(), p.Mutable(), s.data(), 16, o);
    alpha_after_2 = p.alpha[0];
  }
  ASSERT_NEAR(alpha_after_2, 2.1f, 1e-6f);  // 0.8 · 2 + 0.5
  std::vector<Planes> in_place;
  for (unsigned k = 0; k < 3; ++k) in_place.emplace_back(n, 40 + k);
  for (std::size_t i = 0; i < n; ++i)
    in_place[0].alpha[i] = i < 32 ? 2.0f : i < 96 ? alpha_after_2 : 1.25f;
  for (unsigned k = 1; k < 3; ++k) in_place[k].alpha = in_place[0].alpha;
  in_place[2].x[70] = std::numeric_limits<float>::quiet_NaN();
  const std::vector<Planes> copy = in_place;
  std::vector<Planes> out(3, Planes(n, 1));
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
  // posteriors, and the summed surprise (α's KL terms once per pixel either way: the separate
  // calls count them three times, so they are subtracted twice from that sum).
  const std::size_t n = 517;  // not a multiple of 16: the tail runs the scalar code
  for (BatchKernel kernel : {BatchKernel::kScalar, BatchKernel::kVectorised}) {
    SurpriseBatchOptions o;
    o.kernel = kernel;
    std::vector<Planes> prior, separate;
    for (unsigned k = 0; k < 3; ++k) prior.emplace_back(n, 20 + k);
    for (unsigned k = 1; k < 3; ++k) prior[k].alpha = prior[0].alpha;
    prior[1].x[7] = std::numeric_limits<float>::quiet_NaN();  // one channel without data
    separate = prior;
    std::vector<float> shared_surprise(n, 0.0f), separate_surprise(n, 0.0f);
    std::vector<Planes> shared = prior;
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
      const double alpha_terms =
          NormalGammaKLAlphaTerms(double(separate[0].alpha[i]), double(prior[0].alpha[i]));
      ASSERT_NEAR(shared_surprise[i], separate_surprise[i] - 2.0 * alpha_terms,
                  1e-4 * (1.0 + separate_surprise[i]))
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

TEST(NormalGammaBatch, ChannelsMustShareAlpha) {
  Planes a(16, 1), b(16, 2);
  std::vector<float> surprise(16, 0.0f);
  ChannelPlanes c{{a.x.data(), b.x.data()}, {a.View(), b.View()}, {a.Mutable(), b.Mutable()}};
  EXPECT_THROW(UpdateAndAccumulateSurprise(c, surprise.data(), 16, {}), std::invalid_argument);
  c.posterior.pop_back();
  EXPECT_THROW(UpdateAndAccumulateSurprise(c, surprise.data(), 16, {}), std::invalid_argument);
}

}  // namespace
}  // namespace novelty::stats
