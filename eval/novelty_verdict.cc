#include "eval/novelty_verdict.h"

#include <opencv2/core.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace novelty::eval {
namespace {

double Median(std::vector<double> v) {
  const std::size_t n = v.size();
  std::sort(v.begin(), v.end());
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace

void NoveltyVerdictOptions::Check() const {
  if (tail_pixels < 1)
    throw std::invalid_argument("novelty tail_pixels must be >= 1, got " +
                                std::to_string(tail_pixels));
  if (!(z >= 0.0) || !std::isfinite(z))
    throw std::invalid_argument("novelty z must be >= 0 and finite, got " + std::to_string(z));
  if (!(floor_nats >= 0.0) || !std::isfinite(floor_nats))
    throw std::invalid_argument("novelty floor_nats must be >= 0 and finite, got " +
                                std::to_string(floor_nats));
  if (min_frames < 1)
    throw std::invalid_argument("novelty min_frames must be >= 1, got " +
                                std::to_string(min_frames));
}

NoveltyVerdict JudgeNovelty(const std::vector<int>& frame_numbers,
                            const std::vector<PredictionQuality>& frames,
                            const NoveltyVerdictOptions& options) {
  options.Check();
  if (frame_numbers.size() != frames.size())
    throw std::invalid_argument("JudgeNovelty: frame numbers and measurements differ in count");
  NoveltyVerdict v;
  v.tail_pixels = options.tail_pixels;
  std::vector<std::size_t> judged;
  std::vector<double> level;
  for (std::size_t k = 0; k < frames.size(); ++k) {
    if (frames[k].coverage <= 0.0 || !std::isfinite(frames[k].tail_surprise)) continue;  // no say
    judged.push_back(k);
    level.push_back(frames[k].tail_surprise);
  }
  v.frames_judged = int(judged.size());
  if (judged.empty()) return v;
  v.first_frame = frame_numbers[judged.front()];
  v.last_frame = frame_numbers[judged.back()];
  v.median_nats = Median(level);
  // The spread from the frames at or below the median only: something new raises a frame's
  // statistic, never lowers it, so those frames hold the level's own spread however long the new
  // thing stays in view (the lower half of Rousseeuw's double MAD).
  std::vector<double> deviation;
  for (double x : level)
    if (x <= v.median_nats) deviation.push_back(v.median_nats - x);
  v.sigma_nats = 1.4826 * Median(deviation);  // σ of a normal distribution from its MAD
  v.z = options.z;
  v.threshold_nats = std::max(options.floor_nats, v.median_nats + options.z * v.sigma_nats);
  v.at_floor = v.threshold_nats > v.median_nats + options.z * v.sigma_nats;
  NovelStretch run;
  int run_frames = 0;
  const auto close_run = [&] {
    if (run_frames >= options.min_frames) v.stretches.push_back(run);
    run_frames = 0;
  };
  for (std::size_t k : judged) {
    const double x = frames[k].tail_surprise;
    if (x < v.threshold_nats) {
      close_run();
      continue;
    }
    if (run_frames++ == 0) run = {frame_numbers[k], frame_numbers[k], x};
    run.last = frame_numbers[k];
    run.peak_nats = std::max(run.peak_nats, x);
  }
  close_run();
  return v;
}

std::string NoveltyVerdict::Sentence() const {
  if (frames_judged == 0) return "No frame was predicted by the map: nothing could be judged.";
  const std::string rule =
      cv::format("a frame counts when at least %d of its pixels are %.1f nats surprising or more",
                 tail_pixels, threshold_nats) +
      (at_floor ? cv::format(": the floor, above the run's median %.1f nats plus %g × %.1f",
                             median_nats, z, sigma_nats)
                : cv::format(": the run's median %.1f nats plus %g × its robust deviation %.1f",
                             median_nats, z, sigma_nats));
  if (stretches.empty())
    return cv::format("Nothing new in frames %d–%d (%d frames judged; ", first_frame, last_frame,
                      frames_judged) +
           rule + ").";
  std::string s = "Something new in frames ";
  for (std::size_t k = 0; k < stretches.size(); ++k) {
    const NovelStretch& r = stretches[k];
    if (k > 0) s += k + 1 == stretches.size() ? " and " : ", ";
    s += (r.first == r.last ? std::to_string(r.first)
                            : std::to_string(r.first) + "–" + std::to_string(r.last)) +
         cv::format(" (peak %.1f nats)", r.peak_nats);
  }
  return s +
         cv::format(" of the %d frames judged in %d–%d (", frames_judged, first_frame, last_frame) +
         rule + ").";
}

}  // namespace novelty::eval
