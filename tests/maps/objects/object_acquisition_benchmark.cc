// The object map's per-frame cost after the surprise map (DESIGN.md budget: ≤ 10 ms at 320×240):
// morphology and flood fill, features in the focus box, static-feature test and matching against
// a database of 1 000 features. The frame is graf1 (a real photograph) at 320×240 when the shared
// data is there, else smoothed noise; the surprise is high over a 96×80 box (an object of a
// tenth of the frame) and low noise elsewhere.
#include <benchmark/benchmark.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "maps/objects/feature_extractor.h"
#include "maps/objects/object_acquisition.h"

namespace novelty::objects {
namespace {

const core::PinholeCamera kCamera = core::PinholeCamera::FromFov(320, 240, M_PI / 3);

cv::Mat Rgb() {
  const std::string path = std::string(NOVELTY_SOURCE_DIR) + "/../shared/data/graf/graf1.png";
  cv::Mat img = cv::imread(path, cv::IMREAD_COLOR), out;
  if (img.empty()) {
    img.create(480, 640, CV_8UC3);
    cv::RNG(5).fill(img, cv::RNG::UNIFORM, 0, 255);
    cv::GaussianBlur(img, img, {0, 0}, 2.0);
  }
  cv::resize(img, out, {320, 240}, 0, 0, cv::INTER_AREA);
  cv::cvtColor(out, out, cv::COLOR_BGR2RGB);
  return out;
}

void Run(benchmark::State& state, FeatureExtractor extractor) {
  const cv::Mat rgb = Rgb();
  const cv::Mat depth(240, 320, CV_32FC1, cv::Scalar(1.5f));
  cv::Mat surprise(240, 320, CV_32FC1);
  cv::RNG(3).fill(surprise, cv::RNG::UNIFORM, 0.0f, 1.0f);
  surprise(cv::Rect(120, 80, 96, 80)).setTo(30.0f);
  ObjectAcquisitionOptions o;
  o.extractor = extractor;
  ObjectAcquisition acquisition(o);
  // A database of 1 000 features of other objects (random unit descriptors).
  FeatureDatabase& db = acquisition.learner().database();
  cv::Mat d(1000, DescriptorWidth(extractor), CV_32F);
  cv::RNG(9).fill(d, cv::RNG::NORMAL, 0.0, 1.0);
  for (int i = 0; i < d.rows; ++i) cv::normalize(d.row(i), d.row(i));
  for (int k = 0; k < 10; ++k) db.AddFeatures(d.rowRange(100 * k, 100 * (k + 1)), db.AddObject());
  AcquisitionStep step;
  for (auto _ : state) {
    step = acquisition.Process(rgb, depth, surprise, cv::Mat(), kCamera,
                               Eigen::Isometry3d::Identity());
    benchmark::DoNotOptimize(step.learner.selected);
  }
  state.counters["box_px"] = double(step.focus.box.area());
  state.counters["features"] = double(step.extracted);
  state.counters["database"] = double(db.features());
  state.counters["active"] = double(step.learner.active);
}

// Its parts: the focus of attention alone, M-SURF in the box alone, matching 105 features against
// the 1 000 of the database alone.
void BM_FocusOfAttention(benchmark::State& state) {
  cv::Mat surprise(240, 320, CV_32FC1);
  cv::RNG(3).fill(surprise, cv::RNG::UNIFORM, 0.0f, 1.0f);
  surprise(cv::Rect(120, 80, 96, 80)).setTo(30.0f);
  for (auto _ : state) benchmark::DoNotOptimize(FindFocusOfAttention(surprise).box);
}

void BM_MSurfInBox(benchmark::State& state) {
  cv::Mat grey, mask = cv::Mat::zeros(240, 320, CV_8UC1);
  cv::cvtColor(Rgb(), grey, cv::COLOR_RGB2GRAY);
  mask(cv::Rect(120, 80, 96, 80)).setTo(255);
  const cv::Ptr<cv::Feature2D> f = CreateFeatureExtractor(FeatureExtractor::kMSurf);
  std::vector<cv::KeyPoint> keypoints;
  cv::Mat descriptors;
  for (auto _ : state) f->detectAndCompute(grey, mask, keypoints, descriptors);
  state.counters["features"] = double(keypoints.size());
}

void BM_Recognize1000(benchmark::State& state) {
  FeatureDatabase db;
  cv::Mat d(1105, 64, CV_32F);
  cv::RNG(9).fill(d, cv::RNG::NORMAL, 0.0, 1.0);
  for (int i = 0; i < d.rows; ++i) cv::normalize(d.row(i), d.row(i));
  db.AddFeatures(d.rowRange(0, 1000), db.AddObject());
  const cv::Mat selected = d.rowRange(1000, 1105);
  for (auto _ : state) benchmark::DoNotOptimize(db.Recognize(selected).object);
}

BENCHMARK(BM_FocusOfAttention)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_MSurfInBox)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Recognize1000)->Unit(benchmark::kMillisecond);

void BM_AcquisitionFrame_MSurf(benchmark::State& s) { Run(s, FeatureExtractor::kMSurf); }
void BM_AcquisitionFrame_Sift(benchmark::State& s) { Run(s, FeatureExtractor::kSift); }
void BM_AcquisitionFrame_Akaze(benchmark::State& s) { Run(s, FeatureExtractor::kAkaze); }

BENCHMARK(BM_AcquisitionFrame_MSurf)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_AcquisitionFrame_Sift)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_AcquisitionFrame_Akaze)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace novelty::objects

BENCHMARK_MAIN();
