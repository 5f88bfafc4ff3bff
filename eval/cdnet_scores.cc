#include "eval/cdnet_scores.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace novelty::eval {

CdnetCounts& CdnetCounts::operator+=(const CdnetCounts& o) {
  tp += o.tp, fp += o.fp, fn += o.fn, tn += o.tn, shadow += o.shadow, shadow_fp += o.shadow_fp;
  return *this;
}

CdnetCounts CountCdnetFrame(const cv::Mat& mask, const cv::Mat& truth, const cv::Mat& roi) {
  if (mask.type() != CV_8UC1 || truth.type() != CV_8UC1 || mask.size() != truth.size() ||
      (!roi.empty() && (roi.type() != CV_8UC1 || roi.size() != truth.size())))
    throw std::invalid_argument(
        "CountCdnetFrame: mask, ground truth and ROI must be 8-bit grey images of one size");
  CdnetCounts c;
  for (int y = 0; y < truth.rows; ++y) {
    const uchar *m = mask.ptr(y), *t = truth.ptr(y), *r = roi.empty() ? nullptr : roi.ptr(y);
    for (int x = 0; x < truth.cols; ++x) {
      if (r && r[x] == 0) continue;
      const bool set = m[x] != 0;
      switch (t[x]) {
        case kCdnetMotion:
          (set ? c.tp : c.fn) += 1;
          break;
        case kCdnetShadow:
          ++c.shadow;
          c.shadow_fp += set;
          [[fallthrough]];
        case kCdnetStatic:
          (set ? c.fp : c.tn) += 1;
          break;
        case kCdnetUnknown:
        case kCdnetOutsideRoi:
          break;
        default:
          throw std::invalid_argument("CountCdnetFrame: ground-truth label " +
                                      std::to_string(int(t[x])) + " at (" + std::to_string(x) +
                                      ", " + std::to_string(y) +
                                      "); CDnet uses 0, 50, 85, 170 and 255");
      }
    }
  }
  return c;
}

CdnetScores ScoreCdnet(const CdnetCounts& c) {
  const auto ratio = [](double a, double b) {
    return b > 0 ? a / b : std::numeric_limits<double>::quiet_NaN();
  };
  CdnetScores s;
  s.recall = ratio(c.tp, c.tp + c.fn);
  s.specificity = ratio(c.tn, c.tn + c.fp);
  s.fpr = ratio(c.fp, c.fp + c.tn);
  s.fnr = ratio(c.fn, c.tp + c.fn);
  s.pwc = 100 * ratio(c.fn + c.fp, c.tp + c.fn + c.fp + c.tn);
  s.precision = ratio(c.tp, c.tp + c.fp);
  const double pr = s.precision + s.recall;
  s.f_measure = std::isnan(pr) ? pr : pr > 0 ? 2 * s.precision * s.recall / pr : 0.0;
  s.shadow_fpr = ratio(c.shadow_fp, c.shadow);
  return s;
}

}  // namespace novelty::eval
