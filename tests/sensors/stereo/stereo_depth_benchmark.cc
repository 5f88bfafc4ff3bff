// Plane sweep + belief propagation at 320×240 with 64 depth hypotheses (DESIGN budget: ≤ 300 ms),
// on a trinocular rig viewing a textured slanted plane; the stages are also timed separately.
#include <benchmark/benchmark.h>

#include <opencv2/imgproc.hpp>

#include "sensors/stereo/stereo_depth.h"

namespace novelty::sensors {
namespace {

struct Rig {
  cv::Mat center;
  core::PinholeCamera camera = core::PinholeCamera::FromFov(320, 240, M_PI / 3);
  std::vector<SweepView> others;
};

// Side views of a textured scene shifted by a disparity that grows down the image (a floor).
const Rig& TrinocularRig() {
  static const Rig rig = [] {
    Rig r;
    cv::Mat noise(240, 400, CV_8UC3);
    cv::RNG(7).fill(noise, cv::RNG::UNIFORM, 0, 255);
    cv::GaussianBlur(noise, noise, cv::Size(0, 0), 1.5);
    r.center = noise(cv::Rect(40, 0, 320, 240)).clone();
    for (const double b : {-0.12, 0.12}) {
      cv::Mat map_x(240, 320, CV_32F), map_y(240, 320, CV_32F);
      for (int y = 0; y < 240; ++y)
        for (int x = 0; x < 320; ++x) {
          const double depth = 3.0 - 2.0 * y / 240;  // 3 m at the top to 1 m at the bottom
          map_x.at<float>(y, x) = float(40 + x - r.camera.fx * -b / depth);
          map_y.at<float>(y, x) = float(y);
        }
      cv::Mat side;
      cv::remap(noise, side, map_x, map_y, cv::INTER_LINEAR, cv::BORDER_REFLECT);
      Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
      pose.translation().x() = b;
      r.others.push_back({side, r.camera, pose});
    }
    return r;
  }();
  return rig;
}

void BM_PlaneSweep(benchmark::State& state) {
  const Rig& rig = TrinocularRig();
  for (auto _ : state) benchmark::DoNotOptimize(PlaneSweep(rig.center, rig.camera, rig.others, {}));
}
BENCHMARK(BM_PlaneSweep)->Unit(benchmark::kMillisecond);

void BM_BeliefPropagation(benchmark::State& state) {
  const Rig& rig = TrinocularRig();
  const CostVolume volume = PlaneSweep(rig.center, rig.camera, rig.others, {});
  for (auto _ : state) benchmark::DoNotOptimize(RunBeliefPropagation(volume, {}));
}
BENCHMARK(BM_BeliefPropagation)->Unit(benchmark::kMillisecond);

void BM_StereoDepthTrinocular(benchmark::State& state) {
  const Rig& rig = TrinocularRig();
  for (auto _ : state)
    benchmark::DoNotOptimize(ComputeStereoDepth(rig.center, rig.camera, rig.others, {}));
}
BENCHMARK(BM_StereoDepthTrinocular)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace novelty::sensors

BENCHMARK_MAIN();
