#include "maps/stats/normal_gamma_kl.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

namespace novelty::stats {
namespace {

// ln of the normal-gamma density, eq. 4.2.
double LogDensity(const NormalGamma& p, double mu, double lambda) {
  return p.alpha * std::log(p.beta) - std::lgamma(p.alpha) - 0.5 * std::log(2.0 * M_PI * p.sigma) +
         (p.alpha - 0.5) * std::log(lambda) - p.beta * lambda -
         lambda * (mu - p.tau) * (mu - p.tau) / (2.0 * p.sigma);
}

// Eq. 4.14 by 2-D trapezoidal quadrature. Variables: u = ln λ around the posterior's mean
// precision, z = (μ - τ) sqrt(λ/σ); Jacobian dμ dλ = λ sqrt(σ/λ) du dz. The trapezoidal rule is
// exponentially accurate for such smooth, rapidly decaying integrands.
double KLByQuadrature(const NormalGamma& p, const NormalGamma& p0) {
  const double log_m = std::log(p.alpha / p.beta);
  const double v_lo = -(45.0 / p.alpha + 2.0), v_hi = std::log(1.0 + 45.0 / p.alpha) + 1.5;
  const int nu = 3000, nz = 480;
  const double hu = (v_hi - v_lo) / nu, z_max = 12.0, hz = 2.0 * z_max / nz;
  double sum = 0.0;
  for (int i = 0; i <= nu; ++i) {
    const double lambda = std::exp(log_m + v_lo + i * hu);
    const double wu = (i == 0 || i == nu) ? 0.5 : 1.0;
    const double scale = std::sqrt(p.sigma / lambda);
    double inner = 0.0;
    for (int j = 0; j <= nz; ++j) {
      const double mu = p.tau + (-z_max + j * hz) * scale;
      const double lp = LogDensity(p, mu, lambda);
      const double wz = (j == 0 || j == nz) ? 0.5 : 1.0;
      inner += wz * std::exp(lp) * (lp - LogDensity(p0, mu, lambda));
    }
    sum += wu * inner * lambda * scale;
  }
  return sum * hu * hz;
}

std::vector<std::pair<NormalGamma, NormalGamma>> ParameterPairs() {
  std::vector<std::pair<NormalGamma, NormalGamma>> pairs;
  const NormalGamma priors[] = {{1.0, 1.0, 0.0, 5.0},      {2.5, 10.0, 120.0, 0.2},
                                {2.5, 2500.0, 60.0, 5.0},  {0.7, 0.3, 10.0, 1.0},
                                {12.0, 300.0, -3.0, 0.05}, {40.0, 90.0, 200.0, 2.0}};
  const ForgettingUpdateOptions forgetting;
  for (const NormalGamma& p0 : priors) {
    for (double dx : {0.0, 1.0, 7.0, 60.0}) {
      const double x = p0.tau + dx;
      pairs.push_back({UpdateOneSample(p0, x), p0});
      const NormalGammaT<double> q = UpdateWithForgetting<double>(p0, x, forgetting);
      pairs.push_back({{q.alpha, q.beta, q.tau, q.sigma}, p0});
    }
  }
  // Pairs not related by an update: the formula must hold for any two distributions.
  pairs.push_back({{3.0, 2.0, 1.0, 0.5}, {1.5, 4.0, -1.0, 2.0}});
  pairs.push_back({{0.6, 5.0, 50.0, 3.0}, {8.0, 1.0, 40.0, 0.1}});
  return pairs;
}

TEST(NormalGammaKL, ClosedFormMatchesNumericalIntegration) {
  for (const auto& [post, prior] : ParameterPairs()) {
    const double closed = NormalGammaKL<double>(post, prior);
    const double numeric = KLByQuadrature(post, prior);
    EXPECT_NEAR(closed, numeric, 1e-4 * std::abs(numeric) + 1e-12)
        << "post (" << post.alpha << "," << post.beta << "," << post.tau << "," << post.sigma
        << ") prior (" << prior.alpha << "," << prior.beta << "," << prior.tau << "," << prior.sigma
        << ")";
  }
}

TEST(NormalGammaKL, RegroupedFormEqualsEquationsAsPrinted) {
  for (const auto& [post, prior] : ParameterPairs()) {
    const double printed = NormalGammaKLAsPrinted(post, prior);
    EXPECT_NEAR(NormalGammaKL<double>(post, prior), printed, 1e-9 * std::max(1.0, printed));
  }
}

TEST(NormalGammaKL, ZeroForIdenticalDistributions) {
  const NormalGamma ps[] = {InitialPrior(), {2.5, 17.0, 128.0, 0.01}, {40.0, 1e4, -50.0, 3.0}};
  for (const NormalGamma& p : ps) {
    EXPECT_EQ(NormalGammaKL<double>(p, p), 0.0);
    EXPECT_EQ(NormalGammaKL<float>({float(p.alpha), float(p.beta), float(p.tau), float(p.sigma)},
                                   {float(p.alpha), float(p.beta), float(p.tau), float(p.sigma)}),
              0.0f);
  }
}

TEST(NormalGammaKL, NonNegativeOnRandomPairs) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> log_pos(-4.0, 8.0), tau(-300.0, 300.0);
  for (int i = 0; i < 100000; ++i) {
    const NormalGamma a{std::exp(log_pos(rng)), std::exp(log_pos(rng)), tau(rng),
                        std::exp(log_pos(rng))};
    const NormalGamma b{std::exp(log_pos(rng)), std::exp(log_pos(rng)), tau(rng),
                        std::exp(log_pos(rng))};
    ASSERT_GE(NormalGammaKL<double>(a, b), -1e-9 * (1.0 + std::abs(NormalGammaKLAsPrinted(a, b))));
  }
}

TEST(NormalGammaKL, ChannelsSummedWithTwoLogarithmsEqualTheSumOverChannels) {
  // Three channels sharing α (as Y, Cb, Cr): the summed form (logarithms of products) equals the
  // sum of the channels' own terms, in double to rounding and in float to what float keeps —
  // from near-identical distributions (tiny KL) to strongly surprised ones.
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> beta(0.1, 40.0), sigma(0.05, 8.0), tau(0.0, 255.0);
  std::uniform_real_distribution<double> alpha(0.6, 6.0), closeness(-3.0, 0.5);
  for (int trial = 0; trial < 2000; ++trial) {
    const double a0 = alpha(rng), a = a0 * 0.8 + 0.5;
    const double spread = std::pow(10.0, closeness(rng));  // 1e-3 … 3: how far posterior moves
    NormalGamma prior[3], post[3];
    double shift[3], separate = 0.0;
    for (int k = 0; k < 3; ++k) {
      prior[k] = {a0, beta(rng), tau(rng), sigma(rng)};
      shift[k] = spread * (tau(rng) - 128.0) * 0.1;
      post[k] = {a, prior[k].beta * std::exp(spread * (beta(rng) / 40.0 - 0.5)),
                 prior[k].tau + shift[k],
                 prior[k].sigma * std::exp(spread * (sigma(rng) / 8.0 - 0.5))};
      separate += NormalGammaKLOtherTerms(post[k], prior[k], shift[k]);
    }
    const double summed = NormalGammaKLOtherTerms(post, prior, shift, 3);
    ASSERT_NEAR(summed, separate, 1e-12 * (1.0 + std::abs(separate))) << trial;
    NormalGammaT<float> prior_f[3], post_f[3];
    float shift_f[3];
    for (int k = 0; k < 3; ++k) {
      prior_f[k] = {float(prior[k].alpha), float(prior[k].beta), float(prior[k].tau),
                    float(prior[k].sigma)};
      post_f[k] = {float(post[k].alpha), float(post[k].beta), float(post[k].tau),
                   float(post[k].sigma)};
      shift_f[k] = float(shift[k]);
    }
    const float summed_f = NormalGammaKLOtherTerms(post_f, prior_f, shift_f, 3);
    ASSERT_NEAR(summed_f, separate, 2e-6 * (1.0 + std::abs(separate)) + 1e-5) << trial;
  }
}

TEST(NormalGammaKL, SurpriseGrowsWithTheDeviationOfTheObservation) {
  const NormalGammaT<double> prior{2.5, 10.0, 100.0, 0.1};
  const ForgettingUpdateOptions o;
  double last = -1.0;
  for (double dx = 0.0; dx <= 100.0; dx += 5.0) {
    const auto post = UpdateWithForgetting(prior, 100.0 + dx, o);
    const double s = NormalGammaKL(post, prior);
    EXPECT_GT(s, last) << "dx=" << dx;
    last = s;
  }
}

TEST(NormalGammaKL, FastApproximationsDeviateAsDocumented) {
  // At the appearance map's steady state α0 = α = 2.5 the ψ term vanishes and eq. 4.22 is
  // nearly exact; away from it (first frames, α0 = 1 → α = 1.3) the eq. 4.23 error shows.
  NormalGammaKLOptions fast;
  fast.fast_approximations = true;
  const NormalGammaT<double> steady{2.5, 10.0, 100.0, 0.1};
  const auto post = UpdateWithForgetting(steady, 130.0, ForgettingUpdateOptions{});
  EXPECT_NEAR(NormalGammaKL(post, steady, fast), NormalGammaKL(post, steady), 1e-5);
  const NormalGammaT<double> initial{1.0, 1.0, 0.0, 5.0};
  const auto first = UpdateWithForgetting(initial, 100.0, ForgettingUpdateOptions{});
  const double err = std::abs(NormalGammaKL(first, initial, fast) - NormalGammaKL(first, initial));
  EXPECT_GT(err, 0.01);
  EXPECT_LT(err, 0.3 * std::abs(first.alpha - initial.alpha) + 0.01);
}

}  // namespace
}  // namespace novelty::stats
