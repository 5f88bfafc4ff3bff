#include "core/row_windows.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

namespace novelty::core {
namespace {

using core::lanes::I16;

// Every read equals the word in memory, for random rows and bytes, in windows that start
// anywhere, including the image's last rows, whose windows run past its end.
TEST(RowWindows, ReadsEqualTheWordsInMemory) {
  if (!RowWindows::kAvailable) GTEST_SKIP() << "no AVX-512 VBMI on this CPU";
  const int rows = 7, row_bytes = 300;
  std::vector<char> image(std::size_t(rows) * row_bytes);
  std::mt19937 rng(5);
  for (char& c : image) c = char(rng());
  std::uniform_int_distribution<int> any_byte(0, RowWindows::kBytes - 4);
  int checked = 0;
  for (int row0 = 0; row0 < rows; ++row0) {
    const int n = std::min(RowWindows::kMaxRows, rows - row0);
    for (int first : {0, 17, row_bytes - RowWindows::kBytes, row_bytes - 40}) {
      const RowWindows w(image.data(), image.size(), row_bytes, row0, n, first);
      for (int trial = 0; trial < 20; ++trial) {
        I16 row, byte;
        for (int k = 0; k < core::lanes::kLanes; ++k)
          row[k] = int(rng() % n), byte[k] = any_byte(rng);
        const I16 got = w.Read(row, byte);
        for (int k = 0; k < core::lanes::kLanes; ++k) {
          const std::size_t at = std::size_t(row0 + row[k]) * row_bytes + first + byte[k];
          int32_t want = 0;  // bytes past the image read as 0
          std::memcpy(&want, image.data() + at,
                      std::min<std::size_t>(4, image.size() - std::min(at, image.size())));
          ASSERT_EQ(got[k], want) << "rows from " << row0 << ", first " << first << ", lane " << k;
          ++checked;
        }
      }
    }
  }
  EXPECT_EQ(checked, 7 * 4 * 20 * 16);
}

}  // namespace
}  // namespace novelty::core
