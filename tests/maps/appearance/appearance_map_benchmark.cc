// Per-frame cost of the appearance map (prior interpolation + update + surprise) on 320×240
// frames of a simulated arc around a table, and of the differencing baseline; and, for a static
// camera, the appearance map against OpenCV's BackgroundSubtractorMOG2::apply on the same frames.
// Budgets (DESIGN.md): ≤ 5 ms with seven views; static camera no slower than MOG2.
#include <benchmark/benchmark.h>

#include <opencv2/video/background_segm.hpp>
#include <sstream>

#include "maps/appearance/appearance_map.h"
#include "maps/appearance/differencing_map.h"
#include "sim/scenario/scenario_parser.h"
#include "sim/scenario/simulate_frames.h"

namespace novelty::appearance {
namespace {

using Frame = sim::SimulatedFrame;

std::vector<Frame> Simulate(const std::string& camera_line) {
  std::istringstream in(R"(
name bench
frames 60
fps 7
camera 320 240 60
rig rgbd
mount 0.0 0.0 1.10 90 16
material wood phong 0.45 0.28 0.14 0.1 20
material cloth phong 0.92 0.90 0.84
texture cloth stripes 0.25 0.35 0.70 20
material red phong 0.75 0.10 0.08 0.2 30
object table box 1.2 0.8 0.72 wood at 0 0 fixed
object cloth plane 1.3 0.9 cloth at 0 0 on table
object box box 0.14 0.06 0.20 red at 0.25 0.20 on cloth mass 0.4
lamp l1 -1.0 0.8 2.6 2.2 2.1 1.9
)" + camera_line);
  return sim::SimulateFrames(sim::ParseScenario(in, "bench.scn"));
}

const views::PinholeCamera kCam = views::PinholeCamera::FromFov(320, 240, 60.0 * M_PI / 180);

void BM_AppearanceMapMovingCamera(benchmark::State& state) {
  static const std::vector<Frame> frames =
      Simulate("arc 0 0 1.6 -100 -80 0.1\nstop 0.5\narc 0 0 1.6 -80 -100 0.1\n");
  AppearanceMap map;
  for (int k = 0; k < 30; ++k)
    map.Insert(frames[k].rgb, frames[k].depth, kCam, frames[k].T_world_cam);
  std::size_t k = 30, views = 0, n = 0;
  for (auto _ : state) {
    const Frame& f = frames[k];
    views += map.Insert(f.rgb, f.depth, kCam, f.T_world_cam).selected.size();
    ++n;
    k = k + 1 < frames.size() ? k + 1 : 30;
  }
  state.counters["views"] = double(views) / double(n);
}
BENCHMARK(BM_AppearanceMapMovingCamera)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_DifferencingMapMovingCamera(benchmark::State& state) {
  static const std::vector<Frame> frames =
      Simulate("arc 0 0 1.6 -100 -80 0.1\nstop 0.5\narc 0 0 1.6 -80 -100 0.1\n");
  DifferencingMap map;
  for (int k = 0; k < 30; ++k)
    map.Insert(frames[k].rgb, frames[k].depth, kCam, frames[k].T_world_cam);
  std::size_t k = 30;
  for (auto _ : state) {
    const Frame& f = frames[k];
    benchmark::DoNotOptimize(map.Insert(f.rgb, f.depth, kCam, f.T_world_cam).difference.data);
    k = k + 1 < frames.size() ? k + 1 : 30;
  }
}
BENCHMARK(BM_DifferencingMapMovingCamera)->Unit(benchmark::kMillisecond)->UseRealTime();

const std::vector<Frame>& StaticFrames() {
  static const std::vector<Frame> frames = Simulate("static_camera 1.5 -1.2 1.3 0 0 0.75\n");
  return frames;
}

void BM_AppearanceMapStaticCamera(benchmark::State& state) {
  StaticFrames();  // simulate outside the timing
  AppearanceMap map;
  std::size_t k = 0;
  for (auto _ : state) {
    const Frame& f = StaticFrames()[k];
    benchmark::DoNotOptimize(map.Insert(f.rgb, f.depth, kCam, f.T_world_cam).surprise.data);
    k = (k + 1) % StaticFrames().size();
  }
}
BENCHMARK(BM_AppearanceMapStaticCamera)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_Mog2StaticCamera(benchmark::State& state) {
  StaticFrames();
  cv::Ptr<cv::BackgroundSubtractorMOG2> mog2 = cv::createBackgroundSubtractorMOG2();
  cv::Mat mask;
  std::size_t k = 0;
  for (auto _ : state) {
    mog2->apply(StaticFrames()[k].rgb, mask);
    benchmark::DoNotOptimize(mask.data);
    k = (k + 1) % StaticFrames().size();
  }
}
BENCHMARK(BM_Mog2StaticCamera)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace novelty::appearance

BENCHMARK_MAIN();
