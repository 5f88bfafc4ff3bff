// Calling a kernel compiled for a few counts (channel counts, mostly) with a count known only at
// run time: the kernels that keep per-channel sums in registers need the count at compile time.
#pragma once

#include <type_traits>

namespace novelty::core {

/// f(std::integral_constant<int, N>{}) for the first N of Counts equal to `n`, else
/// f(std::integral_constant<int, Fallback>{}) — a kernel for any count (0 by convention) or the
/// largest one. Every call of f must return the same type (a function pointer, typically).
template <int Fallback, int... Counts, class F>
auto WithCount(int n, F&& f) {
  auto result = f(std::integral_constant<int, Fallback>{});
  (void)((n == Counts && ((result = f(std::integral_constant<int, Counts>{})), true)) || ...);
  return result;
}

}  // namespace novelty::core
