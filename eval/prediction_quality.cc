#include "eval/prediction_quality.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <stdexcept>

#include "eval/psnr.h"

namespace novelty::eval {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double UpperMedian(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

std::string Cell(double v) {
  return std::isfinite(v) ? std::to_string(v) : "";
}

}  // namespace

PredictionQuality MeasurePrediction(const cv::Mat& rgb, const cv::Mat& expected,
                                    const cv::Mat& valid, const cv::Mat& surprise,
                                    int tail_pixels) {
  if (tail_pixels < 1) throw std::invalid_argument("MeasurePrediction: tail_pixels must be >= 1");
  PredictionQuality q;
  q.psnr_db = q.mean_surprise = q.p95_surprise = q.tail_surprise = kNaN;
  if (expected.empty() || valid.empty()) return q;
  if (expected.size() != rgb.size() || valid.size() != rgb.size() ||
      (!surprise.empty() && surprise.size() != rgb.size()))
    throw std::invalid_argument("MeasurePrediction: the images' sizes differ");
  const int covered = cv::countNonZero(valid);
  q.coverage = double(covered) / double(rgb.total());
  if (covered == 0) return q;
  q.psnr_db = Psnr(expected, rgb, valid);
  if (surprise.empty()) return q;
  std::vector<double> s;
  s.reserve(std::size_t(covered));
  for (int y = 0; y < rgb.rows; ++y)
    for (int x = 0; x < rgb.cols; ++x)
      if (valid.at<uchar>(y, x) && std::isfinite(surprise.at<float>(y, x)))
        s.push_back(surprise.at<float>(y, x));
  if (s.empty()) return q;
  double sum = 0.0;
  for (double v : s) sum += v;
  q.mean_surprise = sum / double(s.size());
  const std::size_t k = std::min(s.size() - 1, s.size() * 95 / 100);
  std::nth_element(s.begin(), s.begin() + long(k), s.end());
  q.p95_surprise = s[k];
  if (s.size() >= std::size_t(tail_pixels)) {
    const auto at = s.end() - tail_pixels;
    std::nth_element(s.begin(), at, s.end());
    q.tail_surprise = *at;
  }
  return q;
}

PredictionSummary SummarisePrediction(const std::vector<PredictionQuality>& frames) {
  std::vector<double> coverage, psnr, mean, p95;
  for (const PredictionQuality& q : frames) {
    if (q.coverage <= 0.0) continue;
    coverage.push_back(q.coverage);
    if (std::isfinite(q.psnr_db)) psnr.push_back(q.psnr_db);
    if (std::isfinite(q.mean_surprise)) mean.push_back(q.mean_surprise);
    if (std::isfinite(q.p95_surprise)) p95.push_back(q.p95_surprise);
  }
  PredictionSummary s;
  s.frames = int(coverage.size());
  s.median_coverage = UpperMedian(coverage);
  s.median_psnr_db = UpperMedian(psnr);
  s.median_mean_surprise = UpperMedian(mean);
  s.median_p95_surprise = UpperMedian(p95);
  return s;
}

void WritePredictionCsv(const std::string& path, const std::vector<int>& frame_numbers,
                        const std::vector<PredictionQuality>& frames) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error(path + ": cannot be written");
  out << "frame,coverage,psnr_db,mean_surprise,p95_surprise,tail_surprise\n";
  for (std::size_t k = 0; k < frames.size() && k < frame_numbers.size(); ++k) {
    const PredictionQuality& q = frames[k];
    out << frame_numbers[k] << ',' << q.coverage << ',' << Cell(q.psnr_db) << ','
        << Cell(q.mean_surprise) << ',' << Cell(q.p95_surprise) << ',' << Cell(q.tail_surprise)
        << '\n';
  }
  if (!out) throw std::runtime_error(path + ": cannot be written");
}

}  // namespace novelty::eval
