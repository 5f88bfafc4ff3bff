#include "maps/stats/column_medians.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <random>
#include <vector>

namespace novelty::stats {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

// Reference: sort the present values of one column.
float ReferenceMedian(std::vector<float> v, int min_count, float missing) {
  v.erase(std::remove(v.begin(), v.end(), kInf), v.end());
  if (v.empty() || int(v.size()) < min_count) return missing;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5f * (v[n / 2 - 1] + v[n / 2]);
}

TEST(ColumnMedians, EqualsSortingEachColumnForEveryStackHeightWithMissingValues) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> value(-5.0f, 5.0f), coin(0.0f, 1.0f);
  for (int rows = 1; rows <= 17; ++rows) {
    const int width = 37, min_count = std::min(rows, 2);
    std::vector<float> values(rows * width);
    for (float& v : values) v = coin(rng) < 0.2f ? kInf : value(rng);
    std::vector<float> expected(width);
    for (int x = 0; x < width; ++x) {
      std::vector<float> column;
      for (int m = 0; m < rows; ++m) column.push_back(values[m * width + x]);
      expected[x] = ReferenceMedian(column, min_count, -99.0f);
    }
    std::vector<float> out(width);
    ColumnMedians(values.data(), rows, width, min_count, -99.0f, out.data());
    for (int x = 0; x < width; ++x) EXPECT_EQ(out[x], expected[x]) << rows << " rows, x " << x;
  }
}

TEST(ColumnMedians, KnownColumns) {
  // Columns: {3, 1, 2} → 2; {4, inf, 1} → 2.5; {inf, inf, 7} → missing with min_count 2.
  std::vector<float> values = {3, 4, kInf, 1, kInf, kInf, 2, 1, 7};
  float out[3];
  ColumnMedians(values.data(), 3, 3, 2, 0.0f, out);
  EXPECT_EQ(out[0], 2.0f);
  EXPECT_EQ(out[1], 2.5f);
  EXPECT_EQ(out[2], 0.0f);
}

}  // namespace
}  // namespace novelty::stats
