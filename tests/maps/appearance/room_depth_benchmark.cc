// What depth_of_room_at_start adds to the object map's frame: the room's depth span at the
// camera's pose from a snapshot of the appearance map's views — view selection, warping the seven
// selected views' depth meshes (depth alone, no blend) and their nearest and farthest per pixel.
// 320×240; 21 views 1 cm apart facing a wall 1.5 m away that slants by 0.3 m per metre, the
// camera between two of them.
#include <benchmark/benchmark.h>

#include "maps/appearance/room_depth.h"

namespace novelty::appearance {
namespace {

const core::PinholeCamera kCamera = core::PinholeCamera::FromFov(320, 240, M_PI / 3);

Eigen::Isometry3d At(double x) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation().x() = x;
  return T;
}

void BM_RoomDepthSpan(benchmark::State& state) {
  ViewBasedMap map;
  for (int i = 0; i <= 20; ++i) {
    cv::Mat depth(kCamera.height, kCamera.width, CV_32FC1);
    for (int v = 0; v < depth.rows; ++v)
      for (int u = 0; u < depth.cols; ++u)  // the wall Z = 1.5 + 0.3 X in world coordinates
        depth.at<float>(v, u) =
            float((1.5 + 0.3 * 0.01 * i) / (1.0 - 0.3 * (u - kCamera.cx) / kCamera.fx));
    map.Update(kCamera, At(0.01 * i), depth, {}, {});
  }
  RoomDepth room(map);
  cv::Mat span;
  for (auto _ : state) {
    span = room.DepthSpan(kCamera, At(0.105));
    benchmark::DoNotOptimize(span.data);
  }
  state.counters["views"] = double(room.views());
  cv::Mat nearest;
  cv::extractChannel(span, nearest, 0);
  state.counters["covered_share"] = cv::countNonZero(nearest) / double(nearest.total());
}
BENCHMARK(BM_RoomDepthSpan)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace novelty::appearance
BENCHMARK_MAIN();
