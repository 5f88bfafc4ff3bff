#include "maps/stats/column_medians.h"

#include <algorithm>
#include <limits>

namespace novelty::stats {

namespace {

void CompareExchange(float* a, float* b, int width) {
  for (int x = 0; x < width; ++x) {
    const float lo = std::min(a[x], b[x]), hi = std::max(a[x], b[x]);
    a[x] = lo;
    b[x] = hi;
  }
}

}  // namespace

void ColumnMedians(float* values, int rows, int width, int min_count, float missing, float* out) {
  // Odd-even transposition sort: `rows` rounds of neighbour compare-exchanges sort any column.
  for (int round = 0; round < rows; ++round)
    for (int m = round % 2; m + 1 < rows; m += 2)
      CompareExchange(values + m * width, values + (m + 1) * width, width);
  // Missing values (+inf) sorted to the end: the present ones are the first `count`.
  constexpr float kMissing = std::numeric_limits<float>::infinity();
  for (int x = 0; x < width; ++x) {
    int count = rows;
    while (count > 0 && values[(count - 1) * width + x] == kMissing) --count;
    if (count < min_count || count == 0) {
      out[x] = missing;
    } else if (count % 2) {
      out[x] = values[(count / 2) * width + x];
    } else {
      out[x] = 0.5f * (values[(count / 2 - 1) * width + x] + values[(count / 2) * width + x]);
    }
  }
}

}  // namespace novelty::stats
