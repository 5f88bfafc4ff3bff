#include "eval/prediction_quality.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

namespace novelty::eval {
namespace {

// A 10 × 10 frame, the left half predicted 5 levels too bright: PSNR = 10 log10(255² / 25)
// over that half, coverage 0.5; surprise 1…50 there (mean 25.5, 95th percentile 48).
TEST(PredictionQuality, ClosedFormsOnAHalfPredictedFrame) {
  const cv::Mat rgb(10, 10, CV_8UC3, cv::Scalar::all(100));
  const cv::Mat expected(10, 10, CV_8UC3, cv::Scalar::all(105));
  cv::Mat valid = cv::Mat::zeros(10, 10, CV_8UC1);
  valid.colRange(0, 5).setTo(255);
  cv::Mat surprise(10, 10, CV_32FC1, cv::Scalar(std::numeric_limits<float>::quiet_NaN()));
  int k = 0;
  for (int y = 0; y < 10; ++y)
    for (int x = 0; x < 5; ++x) surprise.at<float>(y, x) = float(++k);
  const PredictionQuality q = MeasurePrediction(rgb, expected, valid, surprise);
  EXPECT_DOUBLE_EQ(q.coverage, 0.5);
  EXPECT_NEAR(q.psnr_db, 10 * std::log10(255.0 * 255.0 / 25.0), 1e-9);
  EXPECT_DOUBLE_EQ(q.mean_surprise, 25.5);
  EXPECT_DOUBLE_EQ(q.p95_surprise, 48.0);  // index 47 of 1…50
  EXPECT_DOUBLE_EQ(q.tail_surprise, 1.0);  // the 50th most surprising of 50
  EXPECT_DOUBLE_EQ(MeasurePrediction(rgb, expected, valid, surprise, 3).tail_surprise, 48.0);
  EXPECT_TRUE(std::isnan(MeasurePrediction(rgb, expected, valid, surprise, 51).tail_surprise));
  EXPECT_THROW(MeasurePrediction(rgb, expected, valid, surprise, 0), std::invalid_argument);
  const PredictionQuality first = MeasurePrediction(rgb, cv::Mat(), cv::Mat(), cv::Mat());
  EXPECT_EQ(first.coverage, 0.0);
  EXPECT_TRUE(std::isnan(first.psnr_db));
  EXPECT_THROW(MeasurePrediction(rgb, cv::Mat(5, 5, CV_8UC3), valid, surprise),
               std::invalid_argument);
}

// Medians over the frames the map predicted: an uncovered first frame does not count, and one
// frame of a person walking through does not move the level.
TEST(PredictionQuality, SummaryIsMediansOverPredictedFrames) {
  std::vector<PredictionQuality> frames(5);
  const double psnr[] = {0, 20, 22, 30, 21}, surprise[] = {0, 2, 3, 90, 2.5};
  for (int k = 1; k < 5; ++k) {
    frames[std::size_t(k)].coverage = 0.8 + 0.01 * k;
    frames[std::size_t(k)].psnr_db = psnr[k];
    frames[std::size_t(k)].mean_surprise = surprise[k];
    frames[std::size_t(k)].p95_surprise = 2 * surprise[k];
  }
  const PredictionSummary s = SummarisePrediction(frames);
  EXPECT_EQ(s.frames, 4);
  EXPECT_DOUBLE_EQ(s.median_psnr_db, 22.0);  // upper median of 20, 21, 22, 30
  EXPECT_DOUBLE_EQ(s.median_mean_surprise, 3.0);
  EXPECT_DOUBLE_EQ(s.median_coverage, 0.83);
  const std::string path = (std::filesystem::temp_directory_path() /
                            ("novelty_prediction_" + std::to_string(getpid()) + ".csv"))
                               .string();
  WritePredictionCsv(path, {1, 2, 3, 4, 5}, frames);
  std::ifstream in(path);
  std::string header, first;
  std::getline(in, header);
  std::getline(in, first);
  EXPECT_EQ(header, "frame,coverage,psnr_db,mean_surprise,p95_surprise,tail_surprise");
  EXPECT_EQ(first.substr(0, 4), "1,0,");
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace novelty::eval
