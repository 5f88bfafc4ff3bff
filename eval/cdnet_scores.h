// Scoring a foreground mask the way the CDnet change-detection benchmark does (changedetection.net,
// Goyette et al. 2012; Wang et al. 2014), so that our masks and OpenCV's subtractors are compared
// by one rule. Ground truth labels: 255 motion (positive), 0 static and 50 shadow (negative), 170
// unknown and 85 outside the region of interest (ignored); pixels where the ROI mask is 0, and
// frames outside the temporal ROI, are ignored too. Counts are summed over a sequence's frames and
// the scores computed from the sums, as the benchmark's own code does:
//   recall = TP/(TP+FN), specificity = TN/(TN+FP), FPR = FP/(FP+TN), FNR = FN/(TP+FN),
//   PWC = 100·(FN+FP)/(TP+FN+FP+TN), precision = TP/(TP+FP), F = 2·P·R/(P+R),
// and the false-positive rate on shadow pixels, FP on 50 over the pixels labelled 50.
#pragma once

#include <opencv2/core.hpp>

#include "core/cdnet_labels.h"

namespace novelty::eval {

using core::kCdnetMotion, core::kCdnetOutsideRoi, core::kCdnetShadow, core::kCdnetStatic,
    core::kCdnetUnknown;

struct CdnetCounts {
  long long tp = 0, fp = 0, fn = 0, tn = 0;
  long long shadow = 0, shadow_fp = 0;  ///< pixels labelled shadow, and those the mask set
  CdnetCounts& operator+=(const CdnetCounts& o);
};

/// One frame's counts: `mask` CV_8UC1 (non-zero = foreground), `truth` CV_8UC1 labels of its
/// size, `roi` CV_8UC1 of its size (non-zero = scored) or empty. Throws std::invalid_argument for
/// other types or sizes, or a truth label CDnet does not use.
CdnetCounts CountCdnetFrame(const cv::Mat& mask, const cv::Mat& truth, const cv::Mat& roi = {});

struct CdnetScores {
  double recall = 0, specificity = 0, fpr = 0, fnr = 0, pwc = 0, precision = 0, f_measure = 0;
  double shadow_fpr = 0;  ///< NaN without shadow pixels
};

/// The scores of summed counts; a ratio whose denominator is 0 is NaN (F is 0 when P + R is).
CdnetScores ScoreCdnet(const CdnetCounts& counts);

}  // namespace novelty::eval
