// One 320×240 RGB + depth + id frame of a table scene (floor, walls, table with a striped cloth,
// cup, glass, box, tin plate) with two lamps casting shadows. Budget (DESIGN.md): ≤ 30 ms.
// Args: soft-shadow samples of the first lamp (1 = hard shadows, 16 = soft area lamp).
#include <benchmark/benchmark.h>

#include "core/rigid_pose.h"
#include "sim/render/renderer.h"

namespace novelty::sim {
namespace {

Eigen::Isometry3d At(double x, double y, double z) {
  return Eigen::Isometry3d(Eigen::Translation3d(x, y, z));
}

Material Colour(float r, float g, float b, float ks = 0.0f) {
  Material m;
  m.diffuse = {r, g, b};
  m.specular = ks;
  return m;
}

void BuildTableScene(RayScene& scene) {
  scene.AddObject(MakePlane(8, 8), At(2, 0, 0), Colour(0.5f, 0.45f, 0.4f), 1);
  scene.AddObject(MakeBox({0.1, 8, 3}), At(5, 0, 1.5), Colour(0.8f, 0.8f, 0.75f), 2);
  scene.AddObject(MakeBox({8, 0.1, 3}), At(2, 3, 1.5), Colour(0.75f, 0.8f, 0.8f), 2);
  scene.AddObject(MakeBox({1.2, 0.8, 0.72}), At(2.5, 0, 0.36), Colour(0.4f, 0.25f, 0.1f), 3);
  Material cloth = Colour(0.9f, 0.9f, 0.85f);
  cloth.texture.kind = Texture::Kind::kStripes;
  cloth.texture.second = {0.2f, 0.3f, 0.7f};
  cloth.texture.cells = 1.0f;
  scene.AddObject(MakePlane(1.3, 0.9, 0.05), At(2.5, 0, 0.7205), cloth, 4);
  scene.AddObject(MakeCup(0.04, 0.1), At(2.4, 0.15, 0.771), Colour(0.9f, 0.9f, 0.9f, 0.3f), 5);
  Material glass;
  glass.kind = Material::Kind::kGlass;
  glass.diffuse = {0.95f, 0.97f, 0.95f};
  glass.specular = 0.8f;
  glass.shininess = 200.0f;
  scene.AddObject(MakeCup(0.035, 0.12, 0.003), At(2.6, -0.1, 0.781), glass, 6);
  scene.AddObject(MakeBox({0.15, 0.06, 0.2}), At(2.7, 0.2, 0.821), Colour(0.8f, 0.1f, 0.1f), 7);
  Material tin = Colour(0.7f, 0.7f, 0.72f, 0.9f);
  tin.kind = Material::Kind::kMetal;
  tin.reflectivity = 0.6f;
  tin.shininess = 80.0f;
  scene.AddObject(MakePlate(0.1), At(2.3, -0.2, 0.726), tin, 8);
  scene.Commit();
}

void BM_RenderTableFrame(benchmark::State& state) {
  RayScene scene;
  BuildTableScene(scene);
  Lighting lighting;
  lighting.points.push_back({{1.5, 1.2, 2.2}, {2.0f, 1.8f, 1.5f}, 0.1});
  lighting.points.push_back({{3.5, -1.5, 2.0}, {1.0f, 1.0f, 1.3f}, 0.0});
  RenderOptions options;
  options.soft_shadow_samples = static_cast<int>(state.range(0));
  const core::PinholeCamera camera = core::PinholeCamera::FromFov(320, 240, 1.0);
  const Eigen::Isometry3d pose = core::LookAt({1.2, 0.3, 1.4}, {2.5, 0, 0.75});
  for (auto _ : state) {
    options.frame++;
    const RenderedFrame f = Render(scene, lighting, camera, pose, options);
    benchmark::DoNotOptimize(f.rgb.data);
  }
  state.SetLabel(state.range(0) > 1 ? "one soft area lamp + one hard" : "two hard lamps");
}
BENCHMARK(BM_RenderTableFrame)->Arg(1)->Arg(16)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace novelty::sim

BENCHMARK_MAIN();
