// One Zernike descriptor of order 120 (3 721 magnitudes) of a 60 × 45 region's shape, per grid
// size: the unit of the shape matching of 6.3 (DESIGN.md budget: detection with shape matching
// ≤ 20 ms a frame), and the one-off cost of the tables.
#include <benchmark/benchmark.h>

#include <opencv2/imgproc.hpp>

#include "maps/illumination/zernike_moments.h"

namespace novelty::illumination {
namespace {

void BM_ZernikeDescriptor(benchmark::State& state) {
  const ZernikeMoments z({120, int(state.range(0))});
  cv::Mat shape = cv::Mat::zeros(45, 60, CV_8U);
  cv::ellipse(shape, {30, 22}, {25, 12}, 20.0, 0.0, 360.0, cv::Scalar(255), cv::FILLED);
  for (auto _ : state) benchmark::DoNotOptimize(z.Magnitudes(shape).data());
}
BENCHMARK(BM_ZernikeDescriptor)->Arg(16)->Arg(32)->Arg(64)->Unit(benchmark::kMillisecond);

void BM_ZernikeTables(benchmark::State& state) {
  for (auto _ : state) {
    const ZernikeMoments z({120, int(state.range(0))});
    benchmark::DoNotOptimize(&z);
  }
}
BENCHMARK(BM_ZernikeTables)->Arg(32)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace novelty::illumination

BENCHMARK_MAIN();
