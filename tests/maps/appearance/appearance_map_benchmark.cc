// Per-frame cost of the appearance map (prior interpolation + update + surprise) on 320×240
// frames of a simulated arc around a table, and of the differencing baseline; and, for a static
// camera, the appearance map against OpenCV's BackgroundSubtractorMOG2::apply on the same frames.
// Budgets (DESIGN.md): ≤ 5 ms with seven views (BM_AppearanceMapSevenViews); static camera no
// slower than MOG2.
#include <benchmark/benchmark.h>

#include <opencv2/video/background_segm.hpp>
#include <sstream>

#include "core/rigid_pose.h"
#include "maps/appearance/appearance_map.h"
#include "maps/appearance/differencing_map.h"
#include "maps/appearance/foreground_labels.h"
#include "maps/views/view_selection.h"
#include "sim/render/renderer.h"
#include "sim/scenario/scenario_parser.h"
#include "sim/scenario/scenario_world.h"
#include "sim/scenario/simulate_frames.h"

namespace novelty::appearance {
namespace {

using Frame = sim::SimulatedFrame;

// The table scene; `camera_line` adds the camera's motion.
sim::Scenario BenchScenario(const std::string& camera_line) {
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
  return sim::ParseScenario(in, "bench.scn");
}

std::vector<Frame> Simulate(const std::string& camera_line) {
  return sim::SimulateFrames(BenchScenario(camera_line));
}

const core::PinholeCamera kCam = core::PinholeCamera::FromFov(320, 240, 60.0 * M_PI / 180);

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

// The budget's case: a frame whose seven selection rays each pick a different reference view.
// The views are rendered from cameras 0.25 m out along the virtual camera's seven rays, each
// looking along its ray (δ = 0, φ = 0: its ray's best view), and inserted into a map first; every
// iteration starts from that seven-view map (restored outside the timing, since the insert adds
// the frame as a view) and inserts the virtual camera's frame: warp seven views, blend all
// parameter planes, update, surprise, and the map update — which includes the mesh plan of the
// frame's depth, made beside the tiles, that a moving camera needs at its next warp of the view
// the frame replaced (the restored views come planned).
struct SevenViewMap {
  std::vector<views::ReferenceView> views;
  std::vector<Eigen::Isometry3d> anchors;
  Frame frame;  // the virtual camera's
};

SevenViewMap MakeSevenViewMap() {
  const sim::Scenario s = BenchScenario("static_camera 1.6 -0.6 1.3 0 0 0.75\n");
  sim::ScenarioWorld world(s);
  world.AdvanceTo(0.0);
  sim::RayScene scene;
  world.AddToScene(scene);
  scene.Commit();
  const Eigen::Isometry3d virtual_pose = core::LookAt({1.6, -0.6, 1.3}, {0, 0, 0.75});
  auto render = [&](const Eigen::Isometry3d& pose) {
    const sim::RenderedFrame r = sim::Render(scene, world.CurrentLighting(), kCam, pose, s.render);
    Frame f;
    f.rgb = r.rgb;
    f.depth = r.depth;
    f.T_world_cam = pose;
    return f;
  };
  AppearanceMap builder;
  for (const Eigen::Vector2d& p : views::ViewSelectionOptions{}.ray_points) {
    const Eigen::Vector3d ray =
        (virtual_pose.linear() * kCam.RayCam(p.x() * kCam.width, p.y() * kCam.height)).normalized();
    const Eigen::Vector3d eye = virtual_pose.translation() + 0.25 * ray;
    const Frame f = render(core::LookAt(eye, eye + ray));
    builder.Insert(f.rgb, f.depth, kCam, f.T_world_cam);
  }
  SevenViewMap m;
  for (int j = 0; j < builder.store().size(); ++j) m.views.push_back(builder.store().view(j));
  m.anchors = builder.view_map().anchors();
  m.frame = render(virtual_pose);
  return m;
}

// Argument 1: with the learnt warp-error floor (learn_warp_sigma), which blends the whole prior
// before the tiles and measures the frame's edges against it; 2: also aligned to the prior
// (align_to_prior: the rotation's Gauss-Newton steps and a second prediction).
void BM_AppearanceMapSevenViews(benchmark::State& state) {
  static const SevenViewMap seven = MakeSevenViewMap();
  AppearanceMapOptions options;
  options.learn_warp_sigma = state.range(0) != 0;
  options.align_to_prior = state.range(0) == 2;
  // Every view decoded: a compact map would encode the restored views outside the timing and
  // decode them inside it, which is the storage's cost (BM_DecodeView), not the frame's.
  options.views.storage.decoded_views = 0;
  AppearanceMap map(options);
  std::size_t selected = 0, n = 0;
  for (auto _ : state) {
    state.PauseTiming();
    map.view_map().Restore(seven.views, seven.anchors);
    state.ResumeTiming();
    const Frame& f = seven.frame;
    selected += map.Insert(f.rgb, f.depth, kCam, f.T_world_cam).selected.size();
    ++n;
  }
  state.counters["views"] = double(selected) / double(n);
}
BENCHMARK(BM_AppearanceMapSevenViews)
    ->Arg(0)
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// A compact map (views::ReferenceViewStore, decoded_views > 0) encodes a view when it leaves the
// decoded cache and decodes it when a prediction selects it again: one 320×240 appearance-map
// view (depth, α β σ as halves, τ as floats), 2 threads.
void BM_EncodeView(benchmark::State& state) {
  static const SevenViewMap seven = MakeSevenViewMap();
  std::size_t bytes = 0;
  for (auto _ : state) bytes = views::EncodeView(seven.views[0], {}).BytesUsed();
  state.counters["bytes/pixel"] = double(bytes) / kCam.width / kCam.height;
}
BENCHMARK(BM_EncodeView)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_DecodeView(benchmark::State& state) {
  static const SevenViewMap seven = MakeSevenViewMap();
  const views::EncodedView e = views::EncodeView(seven.views[0], {});
  views::ReferenceView v = seven.views[0];
  for (auto _ : state) {
    views::DecodeInto(e, v);
    benchmark::DoNotOptimize(v.depth.data);
  }
}
BENCHMARK(BM_DecodeView)->Unit(benchmark::kMillisecond)->UseRealTime();

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

// A fixed camera's foreground (foreground_labels.h), built up: /0 the map with predictive
// novelty, /1 holding the foreground's background (hold_above_nats, max_hold_frames 200), /2 also
// the labels (threshold, shadow label) — the whole of experiments/foreground_run's method.
void BM_ForegroundStaticCamera(benchmark::State& state) {
  StaticFrames();
  AppearanceMapOptions o;
  o.predictive_novelty = true;
  const ForegroundLabelOptions labels;
  if (state.range(0) >= 1) {
    o.hold_above_nats = labels.threshold_nats;
    o.max_hold_frames = 200;
  }
  AppearanceMap map(o);
  std::size_t k = 0;
  for (auto _ : state) {
    const Frame& f = StaticFrames()[k];
    const AppearanceProducts p = map.Insert(f.rgb, f.depth, kCam, f.T_world_cam);
    if (state.range(0) >= 2)
      benchmark::DoNotOptimize(ForegroundLabels(p.predictive, f.rgb, p.expected_rgb, labels).data);
    benchmark::DoNotOptimize(p.predictive.data);
    k = (k + 1) % StaticFrames().size();
  }
}
BENCHMARK(BM_ForegroundStaticCamera)
    ->Arg(0)
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

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
