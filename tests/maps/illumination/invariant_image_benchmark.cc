// One viewpoint's invariant image from nine images at 320×240 (DESIGN.md budget: ≤ 30 ms on the
// 2-core machine), each colour mode; and the gradient integration alone, by DCT (even sizes),
// by the mirrored FFT (odd sizes) and by the sparse solve over a region.
#include <benchmark/benchmark.h>

#include <opencv2/imgproc.hpp>

#include "maps/illumination/gradient_integration.h"
#include "maps/illumination/invariant_image.h"

namespace novelty::illumination {
namespace {

// Nine lightings of one textured scene: shading ramps and a shadow that moves.
std::vector<cv::Mat> NineLightings() {
  cv::Mat reflectance(240, 320, CV_32FC3);
  cv::RNG(3).fill(reflectance, cv::RNG::UNIFORM, 30, 220);
  cv::GaussianBlur(reflectance, reflectance, {0, 0}, 1.5);
  std::vector<cv::Mat> images;
  for (int m = 0; m < 9; ++m) {
    cv::Mat lit = reflectance * (0.6 + 0.05 * m);
    lit(cv::Rect(20 * m, 10 * m, 90, 60)) *= 0.35;
    cv::Mat bytes;
    lit.convertTo(bytes, CV_8UC3);
    images.push_back(bytes);
  }
  return images;
}

void BM_InvariantImage(benchmark::State& state) {
  const std::vector<cv::Mat> images = NineLightings();
  InvariantImageOptions options;
  options.colour = InvariantImageOptions::Colour(state.range(0));
  for (auto _ : state) {
    const InvariantImage out = ComputeInvariantImage(images, {}, options);
    benchmark::DoNotOptimize(out.log_invariant.data);
  }
  state.SetLabel(state.range(0) == 0 ? "per channel" : "luminance + chromaticity");
}
BENCHMARK(BM_InvariantImage)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_IntegrateGradients(benchmark::State& state) {
  const cv::Size size(int(state.range(0)), int(state.range(1)));
  cv::Mat gx(size, CV_32F), gy(size, CV_32F);
  cv::RNG(1).fill(gx, cv::RNG::UNIFORM, -1, 1);
  cv::RNG(2).fill(gy, cv::RNG::UNIFORM, -1, 1);
  for (auto _ : state) benchmark::DoNotOptimize(IntegrateGradients(gx, gy).data);
}
BENCHMARK(BM_IntegrateGradients)->Args({320, 240})->Args({321, 241})->Unit(benchmark::kMillisecond);

void BM_IntegrateGradientsInRegion(benchmark::State& state) {
  cv::Mat gx(240, 320, CV_32F), gy(240, 320, CV_32F);
  cv::RNG(1).fill(gx, cv::RNG::UNIFORM, -1, 1);
  cv::RNG(2).fill(gy, cv::RNG::UNIFORM, -1, 1);
  cv::Mat region = cv::Mat::zeros(240, 320, CV_8U);
  cv::circle(region, {160, 120}, 100, cv::Scalar(255), cv::FILLED);
  for (auto _ : state) benchmark::DoNotOptimize(IntegrateGradientsInRegion(gx, gy, region).data);
}
BENCHMARK(BM_IntegrateGradientsInRegion)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace novelty::illumination

BENCHMARK_MAIN();
