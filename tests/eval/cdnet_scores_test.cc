#include "eval/cdnet_scores.h"

#include <gtest/gtest.h>

#include <cmath>

namespace novelty::eval {
namespace {

// A 10 × 10 frame by hand: a 4 × 4 moving object (16 px) at the top left with a 2-px unknown
// rim to its right (8 px), a 3 × 4 shadow (12 px) below it, the rest static (64 px). The mask
// finds 12 of the object, the whole rim (ignored), 6 of the shadow and 2 static pixels.
struct HandFrame {
  cv::Mat truth = cv::Mat(10, 10, CV_8UC1, cv::Scalar(kCdnetStatic));
  cv::Mat mask = cv::Mat(10, 10, CV_8UC1, cv::Scalar(0));
  HandFrame() {
    truth(cv::Rect(0, 0, 4, 4)).setTo(kCdnetMotion);
    truth(cv::Rect(4, 0, 2, 4)).setTo(kCdnetUnknown);
    truth(cv::Rect(0, 4, 4, 3)).setTo(kCdnetShadow);
    mask(cv::Rect(0, 0, 4, 3)).setTo(255);            // 12 of 16 object pixels
    mask(cv::Rect(4, 0, 2, 4)).setTo(255);            // the unknown rim
    mask(cv::Rect(0, 4, 2, 3)).setTo(255);            // 6 of 12 shadow pixels
    mask.at<uchar>(9, 9) = mask.at<uchar>(9, 8) = 1;  // 2 static pixels
  }
};

TEST(CdnetScores, CountsAndScoresOfAFrameDoneByHand) {
  const HandFrame h;
  const CdnetCounts c = CountCdnetFrame(h.mask, h.truth);
  EXPECT_EQ(c.tp, 12);
  EXPECT_EQ(c.fn, 4);
  EXPECT_EQ(c.fp, 8);  // 6 shadow + 2 static
  EXPECT_EQ(c.tn, 64 + 12 - 8);
  EXPECT_EQ(c.shadow, 12);
  EXPECT_EQ(c.shadow_fp, 6);
  const CdnetScores s = ScoreCdnet(c);
  EXPECT_DOUBLE_EQ(s.recall, 12.0 / 16);
  EXPECT_DOUBLE_EQ(s.precision, 12.0 / 20);
  EXPECT_DOUBLE_EQ(s.f_measure, 2 * 0.6 * 0.75 / 1.35);
  EXPECT_DOUBLE_EQ(s.fpr, 8.0 / 76);
  EXPECT_DOUBLE_EQ(s.specificity, 68.0 / 76);
  EXPECT_DOUBLE_EQ(s.fnr, 4.0 / 16);
  EXPECT_DOUBLE_EQ(s.pwc, 100.0 * 12 / 92);
  EXPECT_DOUBLE_EQ(s.shadow_fpr, 0.5);
}

// The ROI mask leaves pixels out; counts add over frames and the scores come from the sums.
TEST(CdnetScores, TheRoiLeavesPixelsOutAndFramesAddUp) {
  const HandFrame h;
  cv::Mat roi(10, 10, CV_8UC1, cv::Scalar(255));
  roi(cv::Rect(0, 0, 2, 10)).setTo(0);  // the left two columns: 8 object, 6 shadow pixels
  const CdnetCounts c = CountCdnetFrame(h.mask, h.truth, roi);
  EXPECT_EQ(c.tp + c.fn, 8);
  EXPECT_EQ(c.shadow, 6);
  EXPECT_EQ(c.shadow_fp, 0) << "the mask's shadow pixels are all in the left columns";
  CdnetCounts sum;
  sum += CountCdnetFrame(h.mask, h.truth);
  sum += CountCdnetFrame(cv::Mat(10, 10, CV_8UC1, cv::Scalar(0)), h.truth);  // finds nothing
  EXPECT_DOUBLE_EQ(ScoreCdnet(sum).recall, 12.0 / 32);
  EXPECT_DOUBLE_EQ(ScoreCdnet(sum).precision, 12.0 / 20);
}

TEST(CdnetScores, EmptyDenominatorsAreNanAndBadInputIsAnError) {
  const CdnetScores s = ScoreCdnet({});
  EXPECT_TRUE(std::isnan(s.recall) && std::isnan(s.f_measure) && std::isnan(s.shadow_fpr));
  CdnetCounts none_found;
  none_found.fn = 5, none_found.tn = 5;
  EXPECT_TRUE(std::isnan(ScoreCdnet(none_found).precision)) << "nothing set: no precision";
  const HandFrame h;
  cv::Mat bad = h.truth.clone();
  bad.at<uchar>(3, 7) = 100;
  EXPECT_THROW(CountCdnetFrame(h.mask, bad), std::invalid_argument);
  EXPECT_THROW(CountCdnetFrame(h.mask, h.truth(cv::Rect(0, 0, 5, 5)).clone()),
               std::invalid_argument);
}

}  // namespace
}  // namespace novelty::eval
