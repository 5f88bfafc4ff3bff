// One 320×240 virtual view from seven 320×240 reference views: warp (mesh rasterisation with
// z-buffer) and blend of an RGB plane. Budget (DESIGN.md): ≤ 3 ms on 2 cores (thesis: 24 ms, GPU).
// The reference views are ray-traced by the simulator around a table scene.
#include <benchmark/benchmark.h>

#include "core/rigid_pose.h"
#include "maps/views/depth_mesh_warper.h"
#include "maps/views/view_blender.h"
#include "maps/views/view_selection.h"
#include "sim/render/renderer.h"

namespace novelty {
namespace {

struct Views {
  core::PinholeCamera camera = core::PinholeCamera::FromFov(320, 240, 1.0);
  std::vector<Eigen::Isometry3d> poses;
  std::vector<cv::Mat> depths, images;
  std::vector<views::MeshPlan> plans;  // as a map keeps them per view
  Eigen::Isometry3d virtual_pose;
};

Views MakeViews() {
  sim::RayScene scene;
  sim::Material cloth;
  cloth.texture.kind = sim::Texture::Kind::kChecker;
  cloth.texture.cells = 10;
  scene.AddObject(sim::MakePlane(6, 6), Eigen::Isometry3d::Identity(), cloth, 1);
  scene.AddObject(sim::MakeBox({0.4, 0.3, 0.5}),
                  Eigen::Isometry3d(Eigen::Translation3d(0, 0, 0.25)), sim::Material{}, 2);
  scene.Commit();
  sim::Lighting light;
  light.points.push_back({{1, 1, 3}, {4, 4, 4}, 0.0});
  Views v;
  for (int i = 0; i < 7; ++i) {
    const double a = -0.6 + 0.2 * i;
    const Eigen::Vector3d eye(2.0 * std::cos(a), 2.0 * std::sin(a), 1.2);
    v.poses.push_back(core::LookAt(eye, {0, 0, 0.2}));
    const sim::RenderedFrame f = sim::Render(scene, light, v.camera, v.poses.back());
    v.depths.push_back(f.depth);
    v.plans.push_back(views::MeshPlanFor(f.depth, views::WarpOptions{}));
    v.images.push_back(f.rgb);
  }
  v.virtual_pose = core::LookAt({2.0 * std::cos(0.05), 2.0 * std::sin(0.05), 1.25}, {0, 0, 0.2});
  return v;
}

// All seven views as WarpMany's sources.
std::vector<views::SourceView> Sources(const Views& v) {
  std::vector<views::SourceView> sources;
  for (int j = 0; j < 7; ++j)
    sources.push_back({&v.camera, &v.poses[j], &v.depths[j], &v.plans[j]});
  return sources;
}

// The seven views warped into the virtual camera (default options), for the blends alone.
std::vector<views::WarpField> Warps(const Views& v) {
  views::DepthMeshWarper warper({}, views::WarpOutputsFor(views::BlendOptions{}));
  std::vector<views::WarpField> warps;
  warper.WarpMany(Sources(v), v.camera, v.virtual_pose, warps);
  return warps;
}

void BM_SynthesiseVirtualView(benchmark::State& state) {
  static const Views v = MakeViews();
  // The warp computes what the (default) blend reads: the map, the depth and the view angles.
  views::WarpOptions wo;
  const views::WarpOutputs outputs = views::WarpOutputsFor(views::BlendOptions{});
  wo.threads = static_cast<int>(state.range(0));
  for (auto _ : state) {
    const std::vector<int> selected = views::SelectViews(v.poses, v.camera, v.virtual_pose);
    std::vector<views::WarpField> warps;
    std::vector<cv::Mat> planes;
    for (int j : selected) {
      warps.push_back(
          views::WarpView(v.camera, v.poses[j], v.depths[j], v.camera, v.virtual_pose, wo, outputs));
      planes.push_back(v.images[j]);
    }
    const views::BlendResult r = views::BlendPlanes(warps, planes);
    benchmark::DoNotOptimize(r.value.data);
    state.counters["views"] = double(selected.size());
  }
}
BENCHMARK(BM_SynthesiseVirtualView)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

// The budget's case: seven reference views warped (whole views per thread) and, with `blend` 1,
// blended; with 0 the warps alone. `planar` is WarpOptions::planar_block (0: every quad alone).
void BM_SevenViews(benchmark::State& state) {
  static const Views v = MakeViews();
  views::WarpOptions wo;
  wo.threads = static_cast<int>(state.range(0));
  const bool blend = state.range(1) != 0;
  wo.planar_block = static_cast<int>(state.range(2));
  views::DepthMeshWarper warper(wo, views::WarpOutputsFor(views::BlendOptions{}));  // as above
  const std::vector<views::SourceView> sources = Sources(v);
  std::vector<views::WarpField> warps;
  for (auto _ : state) {
    warper.WarpMany(sources, v.camera, v.virtual_pose, warps);
    if (blend) {
      const views::BlendResult r = views::BlendPlanes(warps, v.images);
      benchmark::DoNotOptimize(r.value.data);
    }
    benchmark::DoNotOptimize(warps[0].map.data);
  }
  state.SetLabel(blend ? "warp + blend" : "warp");
}
BENCHMARK(BM_SevenViews)
    ->ArgsProduct({{1, 2}, {1, 0}, {0, 8}})
    ->ArgNames({"threads", "blend", "planar"})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// Blending alone: seven precomputed warps, one RGB plane each.
void BM_BlendSevenViews(benchmark::State& state) {
  static const Views v = MakeViews();
  const std::vector<views::WarpField> warps = Warps(v);
  for (auto _ : state) {
    const views::BlendResult r = views::BlendPlanes(warps, v.images);
    benchmark::DoNotOptimize(r.value.data);
  }
}
BENCHMARK(BM_BlendSevenViews)->Unit(benchmark::kMillisecond)->UseRealTime();

// Blending the appearance map's parameter planes (appearance_map.h) from seven precomputed
// warps: per view α, β×3, σ×3 as CV_16FC(7) and τ×3 as CV_32FC3.
void BM_BlendParameterPlanes(benchmark::State& state) {
  static const Views v = MakeViews();
  const std::vector<views::WarpField> warps = Warps(v);
  std::vector<cv::Mat> ab_sigma, tau;
  cv::RNG rng(1);
  for (int j = 0; j < 7; ++j) {
    cv::Mat params(v.camera.height, v.camera.width, CV_32FC(7)), half;
    rng.fill(params, cv::RNG::UNIFORM, 1.0, 10.0);
    params.convertTo(half, CV_16F);
    ab_sigma.push_back(half);
    tau.push_back(cv::Mat(v.camera.height, v.camera.width, CV_32FC3));
    rng.fill(tau.back(), cv::RNG::UNIFORM, 0.0, 255.0);
  }
  for (auto _ : state) {
    benchmark::DoNotOptimize(views::BlendPlanes(warps, ab_sigma).value.data);
    benchmark::DoNotOptimize(views::BlendPlanes(warps, tau).value.data);
  }
}
BENCHMARK(BM_BlendParameterPlanes)->Unit(benchmark::kMillisecond)->UseRealTime();

// Planning a view's mesh: its planar blocks and runs, the quads drawn on their own (once per
// new or replaced reference view: a map that replaces a view every frame pays it every frame).
void BM_PlanMesh(benchmark::State& state) {
  static const Views v = MakeViews();
  for (auto _ : state) {
    benchmark::DoNotOptimize(views::MeshPlanFor(v.depths[3], views::WarpOptions{}).skip.data());
  }
}
BENCHMARK(BM_PlanMesh)->Unit(benchmark::kMillisecond)->UseRealTime();

// Each reference view warped alone (the views differ in how far they are from the virtual one).
void BM_WarpEachView(benchmark::State& state) {
  static const Views v = MakeViews();
  views::WarpOptions wo;
  wo.threads = 1;
  views::DepthMeshWarper warper(wo);
  views::WarpField w;
  const int j = static_cast<int>(state.range(0));
  for (auto _ : state) {
    warper.Warp(v.camera, v.poses[j], v.depths[j], v.camera, v.virtual_pose, w);
    benchmark::DoNotOptimize(w.map.data);
  }
  state.counters["covered"] = w.covered;
}
BENCHMARK(BM_WarpEachView)->DenseRange(0, 6)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_WarpOneView(benchmark::State& state) {
  static const Views v = MakeViews();
  views::WarpOptions wo;
  wo.threads = 1;
  for (auto _ : state) {
    const views::WarpField w =
        views::WarpView(v.camera, v.poses[3], v.depths[3], v.camera, v.virtual_pose, wo);
    benchmark::DoNotOptimize(w.map.data);
  }
}
BENCHMARK(BM_WarpOneView)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace novelty

BENCHMARK_MAIN();
