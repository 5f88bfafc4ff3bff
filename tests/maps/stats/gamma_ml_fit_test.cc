#include "maps/stats/gamma_ml_fit.h"

#include <gtest/gtest.h>

#include <random>

#include <stdexcept>
#include "maps/stats/special_functions.h"

namespace novelty::stats {
namespace {

std::vector<double> GammaSamples(double alpha, double beta, std::size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::gamma_distribution<double> dist(alpha, 1.0 / beta);  // std uses scale = 1/rate
  std::vector<double> y(n);
  for (double& v : y) v = dist(rng);
  return y;
}

TEST(GammaMLFit, RecoversKnownParametersFrom1e5SamplesWithin1Percent) {
  const std::pair<double, double> truths[] = {{0.5, 2.0}, {1.0, 1.0},   {2.0, 0.05},
                                              {7.5, 3.0}, {30.0, 12.0}, {120.0, 0.8}};
  unsigned seed = 100;
  for (const auto& [alpha, beta] : truths) {
    const GammaFit fit = FitGammaML(GammaSamples(alpha, beta, 100000, ++seed));
    EXPECT_EQ(fit.status, GammaFit::Status::kConverged);
    EXPECT_NEAR(fit.alpha, alpha, 0.01 * alpha) << "alpha=" << alpha << " beta=" << beta;
    EXPECT_NEAR(fit.beta, beta, 0.01 * beta) << "alpha=" << alpha << " beta=" << beta;
    EXPECT_LT(fit.iterations, 10);
  }
}

TEST(GammaMLFit, SolvesTheLikelihoodEquationExactly) {
  const std::vector<double> y = {0.3, 1.2, 2.2, 0.9, 4.1, 0.05, 1.7};
  const GammaFit fit = FitGammaML(y);
  double mean = 0, mean_log = 0;
  for (double v : y) mean += v / y.size(), mean_log += std::log(v) / y.size();
  // eq. 2.14 holds at the estimate, and eq. 2.12 gives β.
  EXPECT_NEAR(std::log(fit.alpha) - Digamma(fit.alpha), std::log(mean) - mean_log, 1e-12);
  EXPECT_NEAR(fit.beta, fit.alpha / mean, 1e-12);
}

TEST(GammaMLFit, ZerosAreSkippedAndCountedOrRejected) {
  std::vector<double> y = GammaSamples(3.0, 2.0, 20000, 3);
  const GammaFit clean = FitGammaML(y);
  y.insert(y.begin() + 10, {0.0, -1.0, std::nan("")});
  const GammaFit fit = FitGammaML(y);
  EXPECT_EQ(fit.skipped, 3u);
  EXPECT_EQ(fit.used, 20000u);
  EXPECT_DOUBLE_EQ(fit.alpha, clean.alpha);
  GammaFitOptions strict;
  strict.non_positive = GammaFitOptions::NonPositive::kError;
  try {
    FitGammaML(y, strict);
    FAIL() << "expected an exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("sample 10"), std::string::npos) << e.what();
  }
}

TEST(GammaMLFit, ConstantSamplesGiveDocumentedFallback) {
  const GammaFit fit = FitGammaML(std::vector<double>(50, 2.5));
  EXPECT_EQ(fit.status, GammaFit::Status::kConstant);
  EXPECT_EQ(fit.alpha, GammaFitOptions{}.max_alpha);
  EXPECT_DOUBLE_EQ(fit.alpha / fit.beta, 2.5);  // the mean is kept
}

TEST(GammaMLFit, NoUsableSampleIsAnError) {
  EXPECT_THROW(FitGammaML({}), std::invalid_argument);
  EXPECT_THROW(FitGammaML({0.0, 0.0}), std::invalid_argument);
}

}  // namespace
}  // namespace novelty::stats
