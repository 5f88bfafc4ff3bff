#include "maps/stats/normal_gamma.h"

#include <gtest/gtest.h>

#include <random>
#include <stdexcept>

namespace novelty::stats {
namespace {

void ExpectNear(const NormalGamma& a, const NormalGamma& b, double rel) {
  EXPECT_NEAR(a.alpha, b.alpha, rel * std::abs(b.alpha));
  EXPECT_NEAR(a.beta, b.beta, rel * std::abs(b.beta));
  EXPECT_NEAR(a.tau, b.tau, rel * std::max(1.0, std::abs(b.tau)));
  EXPECT_NEAR(a.sigma, b.sigma, rel * std::abs(b.sigma));
}

TEST(NormalGammaUpdate, OneSampleEqualsNSampleFormulasForNEqualsOne) {
  const NormalGamma priors[] = {InitialPrior(), {2.5, 40.0, 120.0, 0.3}, {0.7, 3.0, -5.0, 12.0}};
  for (const NormalGamma& p : priors) {
    for (double x : {0.0, 17.5, 128.0, 255.0}) {
      ExpectNear(UpdateOneSample(p, x), UpdateSamples(p, {x}), 1e-15);
    }
  }
}

TEST(NormalGammaUpdate, OneSampleKnownAnswer) {
  // α=1, β=1, τ=0, σ=5, x=6: α'=1.5, β'=1+½·36/6=4, τ'=30/6=5, σ'=5/6.
  const NormalGamma post = UpdateOneSample(InitialPrior(), 6.0);
  EXPECT_DOUBLE_EQ(post.alpha, 1.5);
  EXPECT_DOUBLE_EQ(post.beta, 4.0);
  EXPECT_DOUBLE_EQ(post.tau, 5.0);
  EXPECT_DOUBLE_EQ(post.sigma, 5.0 / 6.0);
}

// Conjugacy: N one-sample updates in a row give the N-sample posterior.
TEST(NormalGammaUpdate, SequentialUpdatesEqualBatchUpdate) {
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(100.0, 8.0);
  std::vector<double> z(50);
  for (double& v : z) v = noise(rng);
  NormalGamma seq = InitialPrior();
  for (double v : z) seq = UpdateOneSample(seq, v);
  ExpectNear(seq, UpdateSamples(InitialPrior(), z), 1e-12);
}

TEST(NormalGammaUpdate, ForgettingAlphaFollowsClosedFormAndConverges) {
  const ForgettingUpdateOptions o;  // f = 0.8
  NormalGammaT<double> p{1.0, 1.0, 0.0, 5.0};
  for (int n = 1; n <= 60; ++n) {
    p = UpdateWithForgetting(p, 90.0, o);
    EXPECT_NEAR(p.alpha, AlphaAfterUpdates(1.0, n, o.forgetting_factor), 1e-12) << "n=" << n;
  }
  EXPECT_NEAR(p.alpha, 0.5 / (1.0 - o.forgetting_factor), 1e-5);  // eq. 4.10: α → 2.5
}

TEST(NormalGammaUpdate, ForgettingLearnsConstantInputAndForgetsDeviation) {
  const ForgettingUpdateOptions o;
  NormalGammaT<double> p{1.0, 1.0, 0.0, 5.0};
  for (int n = 0; n < 200; ++n) p = UpdateWithForgetting(p, 90.0, o);
  // τ converges to the observed value; β decays geometrically (β ← f β + tiny) down to the
  // quantisation floor α/12 (α → 2.5: β → 0.2083).
  EXPECT_NEAR(p.tau, 90.0, 1e-6);
  EXPECT_NEAR(p.beta, 2.5 / 12.0, 1e-6);
  // σ settles where σ_p is clamped at σ_min (exp(ξ β/α) = exp(ξ/12) is too small to lift it).
  EXPECT_NEAR(p.sigma, o.sigma_min / (o.sigma_min + 1.0), 1e-9);
  // Without the floor (the thesis's update), β decays geometrically towards 0.
  ForgettingUpdateOptions thesis;
  thesis.min_variance = 0.0;
  NormalGammaT<double> q{1.0, 1.0, 0.0, 5.0};
  for (int n = 0; n < 200; ++n) q = UpdateWithForgetting(q, 90.0, thesis);
  EXPECT_LT(q.beta, 1e-6);
}

TEST(NormalGammaUpdate, ForgettingSteadyStateVarianceTracksNoise) {
  // With noisy input of variance v, β/α approximates v (eq. 4.9: 1/M01 is the expected variance).
  const ForgettingUpdateOptions o;
  std::mt19937 rng(3);
  const double sd = 4.0;
  std::normal_distribution<double> noise(128.0, sd);
  NormalGammaT<double> p{1.0, 1.0, 0.0, 5.0};
  double mean_ratio = 0.0;
  const int burn = 200, n = 20000;
  for (int i = 0; i < burn + n; ++i) {
    p = UpdateWithForgetting(p, noise(rng), o);
    if (i >= burn) mean_ratio += p.beta / p.alpha / n;
  }
  EXPECT_NEAR(mean_ratio, sd * sd, 0.25 * sd * sd);
  EXPECT_NEAR(p.tau, 128.0, 3.0 * sd);
}

TEST(NormalGammaUpdate, AdaptiveSigmaIsClampedAndGrowsWithUncertainty) {
  const ForgettingUpdateOptions o;
  const NormalGammaT<double> certain{2.5, 2.5, 100.0, 0.05};             // variance 1
  const NormalGammaT<double> unsure{2.5, 2500.0, 100.0, 0.05};           // variance 1000
  EXPECT_NEAR(AdaptiveSigma(certain, o), 0.05 * std::exp(0.01), 1e-15);  // eq. 4.8
  EXPECT_DOUBLE_EQ(AdaptiveSigma(unsure, o), o.sigma_max);
  const NormalGammaT<double> tiny{2.5, 2.5, 100.0, 1e-6};
  EXPECT_DOUBLE_EQ(AdaptiveSigma(tiny, o), o.sigma_min);
}

TEST(NormalGammaUpdate, BadOptionsAndParametersAreNamed) {
  ForgettingUpdateOptions o;
  o.forgetting_factor = 1.0;
  EXPECT_THROW(o.Check(), std::invalid_argument);
  o = {};
  o.sigma_max = 0.001;
  try {
    o.Check();
    FAIL() << "expected an exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("sigma_max"), std::string::npos);
  }
  EXPECT_THROW(CheckNormalGamma({-1.0, 1.0, 0.0, 1.0}, "pixel (3,4)"), std::invalid_argument);
  EXPECT_NO_THROW(CheckNormalGamma(InitialPrior(), "initial prior"));
  EXPECT_THROW(UpdateSamples(InitialPrior(), {}), std::invalid_argument);
}

}  // namespace
}  // namespace novelty::stats
