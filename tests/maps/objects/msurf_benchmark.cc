// M-SURF at 320×240 (the robot's camera), and OpenCV's SIFT and AKAZE on the same image: the
// cost of extracting features from a whole frame. The object database extracts them from the
// focus of attention only (thesis 5.1), a fraction of the frame.
#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>
#include <opencv2/features2d.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "maps/objects/msurf.h"

namespace novelty::objects {
namespace {

// graf1 (a real photograph) at 320×240 when the shared data is there, else smoothed noise.
const cv::Mat& Frame() {
  static const cv::Mat frame = [] {
    const std::string path = std::string(NOVELTY_SOURCE_DIR) + "/../shared/data/graf/graf1.png";
    cv::Mat img = cv::imread(path, cv::IMREAD_GRAYSCALE), out;
    if (img.empty()) {
      img.create(480, 640, CV_8U);
      cv::RNG(5).fill(img, cv::RNG::UNIFORM, 0, 255);
      cv::GaussianBlur(img, img, {0, 0}, 2.0);
    }
    cv::resize(img, out, {320, 240}, 0, 0, cv::INTER_AREA);
    return out;
  }();
  return frame;
}

void Run(benchmark::State& state, cv::Feature2D& f) {
  std::vector<cv::KeyPoint> keypoints;
  cv::Mat descriptors;
  for (auto _ : state) {
    f.detectAndCompute(Frame(), cv::noArray(), keypoints, descriptors);
    benchmark::DoNotOptimize(descriptors.data);
  }
  state.counters["keypoints"] = double(keypoints.size());
}

void BM_MSurf(benchmark::State& state) { Run(state, *MSurf::create()); }
void BM_MSurfUpright(benchmark::State& state) {
  MSurfOptions o;
  o.upright = true;
  Run(state, *MSurf::create(o));
}
void BM_Sift(benchmark::State& state) { Run(state, *cv::SIFT::create()); }
void BM_Akaze(benchmark::State& state) { Run(state, *cv::AKAZE::create()); }

BENCHMARK(BM_MSurf)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_MSurfUpright)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Sift)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Akaze)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace novelty::objects

BENCHMARK_MAIN();
