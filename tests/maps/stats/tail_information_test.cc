#include "maps/stats/tail_information.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

namespace novelty::stats {
namespace {

TEST(TailInformation, AnExponentialSampleGivesItsOwnRateTimesTheValue) {
  // X ~ Exp(2): P(X ≥ x) = exp(−2x), so −ln P = 2x — a closed form to compare with.
  std::mt19937 rng(3);
  std::exponential_distribution<float> exponential(2.0f);
  std::vector<float> samples(200000);
  for (float& s : samples) s = exponential(rng);
  const TailTable t = LearnTail(samples);
  EXPECT_NEAR(t.max_information, std::log(200001.0), 1e-9);
  // −ln of an estimated share P from N samples has a standard error of about 1/sqrt(N·P); three
  // of them, plus the interpolation's.
  for (double x : {0.1, 0.5, 1.0, 2.0, 3.0, 4.0})
    EXPECT_NEAR(TailInformation(t, x), 2.0 * x, 0.02 + 3.0 / std::sqrt(200000 * std::exp(-2 * x)))
        << "x = " << x;
  // Beyond the sample: as rare as N samples can tell, however far.
  EXPECT_DOUBLE_EQ(TailInformation(t, 50.0), t.max_information);
  EXPECT_DOUBLE_EQ(TailInformation(t, 1e9), t.max_information);
  EXPECT_EQ(TailInformation(t, -1.0), 0.0);
}

TEST(TailInformation, IsNonDecreasingAlsoOverTiesInTheSample) {
  std::vector<float> samples(1000, 0.0f);  // most samples 0, as most pixels hide no texture
  for (int i = 0; i < 100; ++i) samples[i] = 0.01f * i;
  const TailTable t = LearnTail(samples, 32);
  double last = -1.0;
  for (double x = -0.1; x < 1.2; x += 0.001) {
    const double i = TailInformation(t, x);
    EXPECT_GE(i, last) << x;
    last = i;
  }
  // P(X ≥ 0.5) = 50 / 1000 (samples 0.50 … 0.99): −ln 0.05 = 3.0.
  EXPECT_NEAR(TailInformation(t, 0.5), -std::log(0.05), 0.25);
}

TEST(TailInformation, JustBelowTheLastEntryAndNaNStayInTheTable) {
  // A double that rounds onto the last (float) entry, and NaN, once read past the table's end.
  std::vector<float> samples = {0.0f, 0.5f, 1.0f};
  const TailTable t = LearnTail(samples, 4);
  const double below = std::nextafter(1.0, 0.0);
  EXPECT_LE(TailInformation(t, below), t.max_information);
  EXPECT_GT(TailInformation(t, below), TailInformation(t, 0.5));
  EXPECT_EQ(TailInformation(t, NAN), t.max_information);
}

TEST(TailInformation, TheMeanOfTwoTablesLiesBetweenThem) {
  std::vector<float> a(1000), b(1000);
  for (int i = 0; i < 1000; ++i) a[i] = float(i), b[i] = float(2 * i);
  const TailTable ta = LearnTail(a), tb = LearnTail(b);
  const TailTable m = MeanTail({&ta, &tb}, {3.0, 1.0});
  for (std::size_t k = 0; k < m.values.size(); ++k)
    EXPECT_FLOAT_EQ(m.values[k], 0.75f * ta.values[k] + 0.25f * tb.values[k]);
  EXPECT_DOUBLE_EQ(m.max_information, ta.max_information);
}

TEST(TailInformation, BadInputIsAnError) {
  std::vector<float> one = {1.0f}, nan = {1.0f, NAN};
  EXPECT_THROW(LearnTail(one), std::invalid_argument);
  EXPECT_THROW(LearnTail(nan), std::invalid_argument);
  std::vector<float> two = {1.0f, 2.0f};
  const TailTable a = LearnTail(two), b = LearnTail(two, 8);
  EXPECT_THROW(MeanTail({&a, &b}, {1.0, 1.0}), std::invalid_argument);
  EXPECT_THROW(MeanTail({&a}, {0.0}), std::invalid_argument);
  EXPECT_THROW(MeanTail({}, {}), std::invalid_argument);
}

}  // namespace
}  // namespace novelty::stats
