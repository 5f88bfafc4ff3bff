// Time per frame of the two visual odometries on the same 16 frames of the stereo quarter circle
// (320×240). No budget is set by the sensors issue; reported so the two can be compared. Each
// iteration tracks the whole clip with a fresh odometry, keyframes and re-alignment included.
#include <benchmark/benchmark.h>

#include <vector>

#include "sensors/localization/direct_odometry.h"
#include "sensors/localization/visual_odometry.h"
#include "tests/sensors/localization/quarter_circle.h"

namespace novelty::sensors {
namespace {

const std::vector<std::pair<StereoPair, Eigen::Isometry3d>>& Clip() {
  static const auto clip = [] {
    QuarterCircle run;
    std::vector<std::pair<StereoPair, Eigen::Isometry3d>> frames;
    for (int k = 0; k < 16; ++k) frames.push_back(run.Frame(k));
    return frames;
  }();
  return clip;
}

template <typename Odometry>
void BM_TrackClip(benchmark::State& state) {
  const auto& clip = Clip();
  for (auto _ : state) {
    Odometry vo({}, clip.front().second);
    for (const auto& [pair, truth] : clip) {
      std::string why;
      if (!vo.Track(pair, &why)) state.SkipWithError(why.c_str());
    }
  }
  state.SetItemsProcessed(state.iterations() * int64_t(clip.size()));
  state.SetLabel("items = frames");
}
BENCHMARK_TEMPLATE(BM_TrackClip, DirectOdometry)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_TrackClip, VisualOdometry)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace novelty::sensors

BENCHMARK_MAIN();
