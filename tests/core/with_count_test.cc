#include "core/with_count.h"

#include <gtest/gtest.h>

namespace novelty::core {
namespace {

template <int N>
int Kernel() {
  return N;
}

int KernelFor(int n) {
  return WithCount<0, 1, 3, 7>(n, [](auto count) { return &Kernel<decltype(count)::value>; })();
}

TEST(WithCount, PicksTheKernelOfTheCountOrTheFallback) {
  EXPECT_EQ(KernelFor(1), 1);
  EXPECT_EQ(KernelFor(3), 3);
  EXPECT_EQ(KernelFor(7), 7);
  for (int n : {-1, 0, 2, 4, 8}) EXPECT_EQ(KernelFor(n), 0) << n;
  // A fallback that is one of the counts too (the largest kernel serves what is left).
  const auto largest = [](int n) {
    return WithCount<4, 1, 2, 3>(n, [](auto count) { return &Kernel<decltype(count)::value>; })();
  };
  EXPECT_EQ(largest(2), 2);
  EXPECT_EQ(largest(4), 4);
  EXPECT_EQ(largest(9), 4);
}

}  // namespace
}  // namespace novelty::core
