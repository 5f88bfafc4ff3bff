// Update + surprise per pixel (eq. 4.8-4.21) over a 320×240 frame's three channels, scalar
// (double, one pixel at a time) and vectorised (float, Eigen packets). Reports ns per pixel
// (all three channels) as the counter "per_pixel". Run: build/bin/normal_gamma_batch_benchmark
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "maps/stats/normal_gamma_batch.h"

#include "tests/maps/stats/batch_kernels.h"

namespace novelty::stats {
namespace {

constexpr int kWidth = 320, kHeight = 240, kChannels = 3;

void BM_UpdateAndSurprise(benchmark::State& state) {
  const auto kernel = static_cast<BatchKernel>(state.range(0));
  const std::size_t n = kWidth * kHeight;
  std::mt19937 rng(1);
  std::uniform_real_distribution<float> t(0.0f, 255.0f), noise(-6.0f, 6.0f);
  std::vector<float> alpha(n * kChannels, 2.5f), beta(n * kChannels, 40.0f), tau(n * kChannels),
      sigma(n * kChannels, 0.1f), x(n * kChannels);
  for (std::size_t i = 0; i < x.size(); ++i) {
    tau[i] = t(rng);
    x[i] = tau[i] + noise(rng);
  }
  std::vector<float> pa(alpha), pb(beta), pt(tau), ps(sigma), surprise(n);
  KernelOptions o;
  o.kernel = kernel;
  for (auto _ : state) {
    std::fill(surprise.begin(), surprise.end(), 0.0f);
    // Y, Cb, Cr at once, sharing channel 0's α plane, as the appearance map calls it.
    ChannelPlanes c;
    for (int k = 0; k < kChannels; ++k) {
      const std::size_t off = k * n;
      c.x.push_back(x.data() + off);
      c.prior.push_back({alpha.data(), beta.data() + off, tau.data() + off, sigma.data() + off});
      c.posterior.push_back({pa.data(), pb.data() + off, pt.data() + off, ps.data() + off});
    }
    UpdateAndAccumulateSurprise(c, surprise.data(), n, o);
    benchmark::DoNotOptimize(surprise.data());
    benchmark::ClobberMemory();
  }
  state.counters["per_pixel"] =
      benchmark::Counter(static_cast<double>(n), benchmark::Counter::kIsIterationInvariantRate |
                                                     benchmark::Counter::kInvert);
  state.SetLabel(kernel == BatchKernel::kScalar ? "scalar double" : "vectorised float");
}
BENCHMARK(BM_UpdateAndSurprise)
    ->Arg(static_cast<int>(BatchKernel::kScalar))
    ->Arg(static_cast<int>(BatchKernel::kVectorised))
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace novelty::stats

BENCHMARK_MAIN();
