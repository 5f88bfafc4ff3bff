// How well the map predicted a frame, without ground truth: the expected image τ (the prior's
// mean, eq. 4.8) against the camera image by PSNR over the pixels the map covers, always with
// that coverage, and the surprise there — on an unchanged scene the false-surprise level a user's
// threshold must stand above. Per frame for frames.csv, and summarised over a run by medians (a
// few frames with a person walking through must not move the level).
#pragma once

#include <opencv2/core.hpp>
#include <string>
#include <vector>

namespace novelty::eval {

struct PredictionQuality {
  double coverage = 0.0;       ///< share of the frame's pixels the map predicts (0…1)
  double psnr_db = 0.0;        ///< of τ against the frame over those pixels; NaN when none
  double mean_surprise = 0.0;  ///< nats, over those pixels; NaN when none
  double p95_surprise = 0.0;   ///< nats, the 95th percentile there; NaN when none
  /// nats, at the `tail_pixels`-th most surprising predicted pixel: how surprising the most
  /// surprising small region is, whatever the frame's size (novelty_verdict.h); NaN when fewer.
  double tail_surprise = 0.0;
};

/// `rgb` CV_8UC3 (the camera's), `expected` CV_8UC3, `valid` CV_8UC1 (non-zero: predicted),
/// `surprise` CV_32FC1 (NaN where not predicted). Empty products (a first frame) give coverage 0.
/// Throws std::invalid_argument for sizes that differ or tail_pixels < 1.
PredictionQuality MeasurePrediction(const cv::Mat& rgb, const cv::Mat& expected,
                                    const cv::Mat& valid, const cv::Mat& surprise,
                                    int tail_pixels = 50);

struct PredictionSummary {
  int frames = 0;  ///< frames with some coverage
  double median_coverage = 0.0, median_psnr_db = 0.0, median_mean_surprise = 0.0,
         median_p95_surprise = 0.0;
};

/// Medians over the frames with coverage > 0 (all zeros when there are none).
PredictionSummary SummarisePrediction(const std::vector<PredictionQuality>& frames);

/// Writes frames.csv-style rows: frame,coverage,psnr_db,mean_surprise,p95_surprise,tail_surprise
/// (blank where NaN). Throws std::runtime_error naming `path`.
void WritePredictionCsv(const std::string& path, const std::vector<int>& frame_numbers,
                        const std::vector<PredictionQuality>& frames);

}  // namespace novelty::eval
