// Novelty under changing light for one 320×240 frame at a learnt viewpoint (6.3: illumination
// image, information maps, regions above T_Y, Zernike shape matching, Δ) — DESIGN.md budget
// ≤ 20 ms including the shape matching. The viewpoint is learnt from nine lightings of a textured
// scene with a highlight and a moving shadow; the frame adds a dark object and shows the
// highlight again.
#include <benchmark/benchmark.h>

#include <opencv2/imgproc.hpp>

#include "maps/illumination/illumination_novelty.h"

namespace novelty::illumination {
namespace {

cv::Mat Lit(const cv::Mat& reflectance, const cv::Mat& highlight, int m, bool with_highlight) {
  cv::Mat lighting(reflectance.size(), CV_32FC3, cv::Scalar::all(0.7 + 0.05 * m));
  if (with_highlight) lighting.setTo(cv::Scalar::all(2.5), highlight);
  lighting(cv::Rect(20 + 25 * m, 150, 60, 40)) *= 0.3;  // a shadow that moves
  cv::Mat out = reflectance.mul(lighting), bytes;
  out.convertTo(bytes, CV_8UC3);
  return bytes;
}

void BM_DetectIlluminationNovelty(benchmark::State& state) {
  cv::Mat reflectance(240, 320, CV_32FC3);
  cv::RNG(3).fill(reflectance, cv::RNG::UNIFORM, 40, 160);
  cv::GaussianBlur(reflectance, reflectance, {0, 0}, 2.0);
  cv::Mat highlight = cv::Mat::zeros(240, 320, CV_8U);
  cv::ellipse(highlight, {120, 80}, {30, 14}, 20, 0, 360, cv::Scalar(255), cv::FILLED);
  std::vector<cv::Mat> training;
  for (int m = 0; m < 9; ++m) training.push_back(Lit(reflectance, highlight, m, m % 4 == 1));
  const ZernikeMoments zernike;
  const InvariantImage invariant = ComputeInvariantImage(training);
  IlluminationModelOptions options;
  options.missing_texture = state.range(0) != 0;
  const ViewpointIllumination viewpoint =
      MakeViewpoint(invariant, LearnIlluminationModel(invariant, {}, options), 16, &zernike);
  cv::Mat frame = Lit(reflectance, highlight, 4, true);
  frame(cv::Rect(220, 60, 40, 50)).setTo(cv::Scalar(20, 15, 60));  // a new dark object
  int regions = 0;
  for (auto _ : state) {
    const IlluminationNovelty n = DetectIlluminationNovelty(frame, viewpoint, zernike);
    regions = n.region_count;
    benchmark::DoNotOptimize(n.novelty.data);
  }
  state.counters["regions"] = regions;
  state.counters["stored_shapes"] = double(viewpoint.shapes.size());
}
// /0: the thesis's Δ; /1: with the missing texture (i_T).
BENCHMARK(BM_DetectIlluminationNovelty)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace novelty::illumination

BENCHMARK_MAIN();
