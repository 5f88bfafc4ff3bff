// What depth_of_room_at_start adds to the object map's frame: the room's depth span at the
// camera's pose from a snapshot of the appearance map's views — view selection, warping the
// selected views' depth meshes (depth alone, no blend) and their nearest and farthest per pixel —
// and, once, taking the snapshot. 320×240; 60 views on an arc of radius 1.5 m around a wall, each
// looking at the wall's centre (the robot circling a table, as in the experiment of 5.2), held as
// the appearance map holds them (12 decoded, the rest compact); the camera between two views.
#include <benchmark/benchmark.h>

#include "core/rigid_pose.h"
#include "maps/appearance/room_depth.h"
#include "maps/views/view_selection.h"

namespace novelty::appearance {
namespace {

const core::PinholeCamera kCamera = core::PinholeCamera::FromFov(320, 240, M_PI / 3);

// On the arc at `deg` degrees, looking at the origin.
Eigen::Isometry3d OnArc(double deg) {
  const double a = deg * M_PI / 180.0;
  return core::LookAt({1.5 * std::sin(a), -1.5 * std::cos(a), 0.0}, {0, 0, 0});
}

// The depth (+Z) at each pixel of a camera at T of the wall y = 0.3 (0.3 m behind the origin).
cv::Mat WallDepth(const Eigen::Isometry3d& T) {
  cv::Mat depth(kCamera.height, kCamera.width, CV_32FC1);
  for (int v = 0; v < depth.rows; ++v)
    for (int u = 0; u < depth.cols; ++u) {
      const Eigen::Vector3d ray((u - kCamera.cx) / kCamera.fx, (v - kCamera.cy) / kCamera.fy, 1);
      const Eigen::Vector3d d = T.linear() * ray;  // world direction; +Z of the camera is 1
      const double t = (0.3 - T.translation().y()) / d.y();
      depth.at<float>(v, u) = d.y() > 1e-6 ? float(t) : 0.0f;
    }
  return depth;
}

// Default storage: the appearance map's.
void Fill(ViewBasedMap& map) {
  const cv::Mat plane(kCamera.height, kCamera.width, CV_16FC3, cv::Scalar::all(0));
  for (int i = 0; i < 60; ++i) {
    const Eigen::Isometry3d T = OnArc(-30.0 + i);
    map.Update(kCamera, T, WallDepth(T), {{"p", plane.clone()}}, {});
    map.Predict(kCamera, T, {{"p", 3}});  // keeps the store's cache as a running map does
  }
}

void BM_RoomDepthSpan(benchmark::State& state) {
  ViewBasedMap map;
  Fill(map);
  RoomDepth room(map);
  const Eigen::Isometry3d at = OnArc(0.5);
  cv::Mat span;
  for (auto _ : state) {
    span = room.DepthSpan(kCamera, at);
    benchmark::DoNotOptimize(span.data);
  }
  std::vector<Eigen::Isometry3d> poses;
  for (int i = 0; i < 60; ++i) poses.push_back(OnArc(-30.0 + i));
  state.counters["selected"] = double(views::SelectViewsForRays(poses, kCamera, at).views.size());
  cv::Mat nearest;
  cv::extractChannel(span, nearest, 0);
  state.counters["covered_share"] = cv::countNonZero(nearest) / double(nearest.total());
}
BENCHMARK(BM_RoomDepthSpan)->Unit(benchmark::kMillisecond);

// Taking the snapshot at the first frame: 12 depths shared, 48 copied encoded.
void BM_RoomDepthSnapshot(benchmark::State& state) {
  ViewBasedMap map;
  Fill(map);
  for (auto _ : state) {
    RoomDepth room(map);
    benchmark::DoNotOptimize(room.views());
  }
}
BENCHMARK(BM_RoomDepthSnapshot)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace novelty::appearance

BENCHMARK_MAIN();
