#include "maps/stats/special_functions.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace novelty::stats {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::vector<double> Arguments() {
  std::vector<double> z;
  for (double v = 1e-3; v < 1e6; v *= 1.07) z.push_back(v);
  return z;
}

TEST(SpecialFunctions, LogGammaMatchesLibm) {
  for (double z : Arguments()) {
    const double ref = std::lgamma(z);
    EXPECT_NEAR(LogGamma(z), ref, 2e-13 * std::max(1.0, std::abs(ref))) << "z=" << z;
  }
}

TEST(SpecialFunctions, LogGammaKnownValues) {
  EXPECT_NEAR(LogGamma(1.0), 0.0, 1e-14);
  EXPECT_NEAR(LogGamma(2.0), 0.0, 1e-14);
  EXPECT_NEAR(LogGamma(0.5), 0.5 * std::log(kPi), 1e-14);
  EXPECT_NEAR(LogGamma(10.0), std::log(362880.0), 1e-13);
}

TEST(SpecialFunctions, DigammaKnownValues) {
  EXPECT_NEAR(Digamma(1.0), -kEulerGamma, 1e-13);
  EXPECT_NEAR(Digamma(0.5), -kEulerGamma - 2.0 * std::log(2.0), 1e-13);
  EXPECT_NEAR(Digamma(2.5), -kEulerGamma - 2.0 * std::log(2.0) + 2.0 + 2.0 / 3.0, 1e-13);
}

TEST(SpecialFunctions, DigammaIsDerivativeOfLogGammaAndSatisfiesRecurrence) {
  for (double z : Arguments()) {
    // ψ(z+1) = ψ(z) + 1/z
    EXPECT_NEAR(Digamma(z + 1.0), Digamma(z) + 1.0 / z, 1e-12 * std::max(1.0, 1.0 / z));
    if (z > 0.05 && z < 1e4) {
      const double h = 1e-5 * z;
      const double numeric = (std::lgamma(z + h) - std::lgamma(z - h)) / (2 * h);
      EXPECT_NEAR(Digamma(z), numeric, 1e-6 * std::max(1.0, std::abs(numeric))) << "z=" << z;
    }
  }
}

TEST(SpecialFunctions, TrigammaKnownValuesAndDerivative) {
  EXPECT_NEAR(Trigamma(1.0), kPi * kPi / 6.0, 1e-13);
  EXPECT_NEAR(Trigamma(0.5), kPi * kPi / 2.0, 1e-12);
  for (double z : Arguments()) {
    EXPECT_NEAR(Trigamma(z), Trigamma(z + 1.0) + 1.0 / (z * z), 1e-12 * Trigamma(z));
    if (z > 0.05 && z < 1e4) {
      const double h = 1e-4 * z;
      const double numeric = (Digamma(z + h) - Digamma(z - h)) / (2 * h);
      EXPECT_NEAR(Trigamma(z), numeric, 1e-6 * Trigamma(z)) << "z=" << z;
    }
  }
}

// Eigen's SIMD log may differ from libm's in the last bit; nothing more.
TEST(SpecialFunctions, EigenArraysGiveTheScalarResults) {
  Eigen::Array<double, 4, 1> z(0.3, 1.7, 2.5, 40.0);
  const Eigen::Array<double, 4, 1> lg = LogGamma(z), dg = Digamma(z), tg = Trigamma(z);
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(lg[i], LogGamma(z[i]), 1e-14 * std::max(1.0, std::abs(lg[i])));
    EXPECT_NEAR(dg[i], Digamma(z[i]), 1e-14 * std::max(1.0, std::abs(dg[i])));
    EXPECT_NEAR(tg[i], Trigamma(z[i]), 1e-14 * std::max(1.0, std::abs(tg[i])));
  }
}

// The thesis's GPU approximations: the errors documented in special_functions.h.
TEST(SpecialFunctions, ThesisApproximationErrorsAreAsDocumented) {
  EXPECT_NEAR(std::abs(LogGammaStirling(0.5) - std::lgamma(0.5)), 1.6e-2, 0.05e-2);
  EXPECT_NEAR(std::abs(LogGammaStirling(2.5) - std::lgamma(2.5)), 8.1e-7, 0.05e-7);
  EXPECT_NEAR(std::abs(DigammaTruncated(0.5) - Digamma(0.5)), 0.087, 0.001);
  EXPECT_NEAR(std::abs(DigammaTruncated(2.5) - Digamma(2.5)), 0.374, 0.001);
  // Stirling improves with z; the truncated digamma series gets worse.
  EXPECT_LT(std::abs(LogGammaStirling(20.0) - std::lgamma(20.0)), 1e-12);
  EXPECT_GT(std::abs(DigammaTruncated(20.0) - Digamma(20.0)), 1.0);
}

}  // namespace
}  // namespace novelty::stats
