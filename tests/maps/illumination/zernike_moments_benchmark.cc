// One Zernike descriptor of a 60 × 45 region's shape — the default (order 20 on 32 cells), the
// thesis's order 120 (3 721 magnitudes) on 32 and on 128 cells: the unit of the shape matching of
// 6.3 (DESIGN.md budget: detection with shape matching ≤ 20 ms a frame); and the one-off cost of
// the tables.
#include <benchmark/benchmark.h>

#include <opencv2/imgproc.hpp>

#include "maps/illumination/zernike_moments.h"

namespace novelty::illumination {
namespace {

void BM_ZernikeDescriptor(benchmark::State& state) {
  const ZernikeMoments z({int(state.range(0)), int(state.range(1))});
  cv::Mat shape = cv::Mat::zeros(45, 60, CV_8U);
  cv::ellipse(shape, {30, 22}, {25, 12}, 20.0, 0.0, 360.0, cv::Scalar(255), cv::FILLED);
  for (auto _ : state) benchmark::DoNotOptimize(z.Magnitudes(shape).data());
}
BENCHMARK(BM_ZernikeDescriptor)
    ->Args({20, 32})
    ->Args({120, 32})
    ->Args({120, 128})
    ->Unit(benchmark::kMillisecond);

void BM_ZernikeTables(benchmark::State& state) {
  for (auto _ : state) {
    const ZernikeMoments z({int(state.range(0)), int(state.range(1))});
    benchmark::DoNotOptimize(&z);
  }
}
BENCHMARK(BM_ZernikeTables)->Args({20, 32})->Args({120, 32})->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace novelty::illumination

BENCHMARK_MAIN();
