#include "maps/stats/predictive_novelty.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace novelty::stats {
namespace {

// p(x) = ∫∫ N(x; μ, 1/λ) N(μ; τ, σ/λ) Gamma(λ; α, β) dμ dλ by the midpoint rule on a fine grid
// — the model itself, integrated without the Student-t derivation.
double IntegratedDensity(const NormalGamma& p, double x) {
  const auto normal = [](double v, double mean, double var) {
    return std::exp(-0.5 * (v - mean) * (v - mean) / var) / std::sqrt(2 * M_PI * var);
  };
  const auto gamma = [&](double l) {
    return std::exp(p.alpha * std::log(p.beta) - std::lgamma(p.alpha) +
                    (p.alpha - 1) * std::log(l) - p.beta * l);
  };
  // λ on a logarithmic grid (far x draw their density from small λ) up to where the gamma's
  // tail is negligible; μ over ±12 of its standard deviations at that λ.
  const double t_min = std::log(1e-7 / p.beta),
               t_max = std::log((p.alpha + 30 * std::sqrt(p.alpha) + 30) / p.beta);
  const int nl = 6000, nm = 800;
  const double dt = (t_max - t_min) / nl;
  double sum = 0;
  for (int i = 0; i < nl; ++i) {
    const double l = std::exp(t_min + (i + 0.5) * dt);
    const double sd = std::sqrt(p.sigma / l), lo = p.tau - 12 * sd, hi = p.tau + 12 * sd;
    const double dm = (hi - lo) / nm;
    double inner = 0;
    for (int j = 0; j < nm; ++j) {
      const double m = lo + (j + 0.5) * dm;
      inner += normal(x, m, 1 / l) * normal(m, p.tau, p.sigma / l);
    }
    sum += inner * dm * gamma(l) * l * dt;  // dλ = λ dt
  }
  return sum;
}

TEST(PredictiveNovelty, IsTheNegativeLogOfTheModelsIntegratedDensity) {
  for (const NormalGamma& p : {NormalGamma{1.0, 1.0, 0.0, 5.0}, NormalGamma{2.5, 40.0, 120.0, 0.04},
                               NormalGamma{3.0, 9.0, -4.0, 1.0}}) {
    const double sd = std::sqrt(p.beta * (1 + p.sigma) / p.alpha);
    for (double k : {0.0, 0.7, 2.0, 5.0}) {
      const double x = p.tau + k * sd;
      const double numeric = -std::log(IntegratedDensity(p, x));
      EXPECT_NEAR(PredictiveNegLogDensity(p, x), numeric, 2e-4)
          << "alpha " << p.alpha << " beta " << p.beta << " at " << k << " sd";
    }
  }
}

TEST(PredictiveNovelty, TheDensityIntegratesToOne) {
  const NormalGamma p{2.5, 40.0, 120.0, 0.04};
  double total = 0;
  const double dx = 0.01;
  for (double x = -2000; x < 2240; x += dx)  // the t's tails with ν = 5 decay as |x|^-6
    total += std::exp(-PredictiveNegLogDensity(p, x + 0.5 * dx)) * dx;
  EXPECT_NEAR(total, 1.0, 1e-6);
}

// The channels' sum with shared α, in float, is the sum of the single channels in double.
TEST(PredictiveNovelty, ChannelsSharingAlphaSumTheirTerms) {
  const NormalGamma d[3] = {{2.5, 30.0, 140.0, 0.05}, {2.5, 2.0, 3.0, 0.05}, {2.5, 1.5, -2.0, 0.1}};
  const double xd[3] = {150.0, 1.0, 4.0};
  double expected = 0;
  for (int k = 0; k < 3; ++k) expected += PredictiveNegLogDensity(d[k], xd[k]);
  NormalGammaT<float> f[3];
  float xf[3];
  for (int k = 0; k < 3; ++k) {
    f[k] = {float(d[k].alpha), float(d[k].beta), float(d[k].tau), float(d[k].sigma)};
    xf[k] = float(xd[k]);
  }
  const float got = PredictiveNegLogDensityChannels(f, xf, 3, PredictiveAlphaTerm(2.5f));
  EXPECT_NEAR(got, expected, 1e-5 * std::abs(expected));
  EXPECT_NEAR(PredictiveNegLogDensityChannels(d, xd, 3, PredictiveAlphaTerm(2.5)), expected, 1e-12);
}

// The two-logarithm form is the exact sum: within 1e-6 nats in double from α = 0.5 on, and within
// the float rounding of its inputs in float.
TEST(PredictiveNovelty, TheTwoLogarithmFormIsTheExactSum) {
  for (double alpha = 0.5; alpha < 200; alpha *= 1.3) {
    const NormalGamma d[3] = {
        {alpha, 30.0, 140.0, 0.05}, {alpha, 2.0, 3.0, 0.5}, {alpha, 1.5, -2.0, 4.0}};
    const double xd[3] = {171.0, 1.0, 4.0};
    const double exact = PredictiveNegLogDensityChannels(d, xd, 3, PredictiveAlphaTerm(alpha));
    double u, v, offset;
    PredictiveLogArguments(d, xd, 3, u, v, offset);
    EXPECT_NEAR(0.5 * std::log(u) + (alpha + 0.5) * std::log(v) + offset, exact, 1e-6)
        << "alpha " << alpha;
    NormalGammaT<float> f[3];
    float xf[3], uf, vf, of;
    for (int k = 0; k < 3; ++k) {
      f[k] = {float(d[k].alpha), float(d[k].beta), float(d[k].tau), float(d[k].sigma)};
      xf[k] = float(xd[k]);
    }
    PredictiveLogArguments(f, xf, 3, uf, vf, of);
    EXPECT_NEAR(0.5f * std::log(uf) + (float(alpha) + 0.5f) * std::log(vf) + of, exact,
                2e-6 * (alpha + 1) * std::abs(exact) + 1e-4)
        << "alpha " << alpha << " in float";
  }
}

}  // namespace
}  // namespace novelty::stats
