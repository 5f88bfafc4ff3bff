// An ROC as a plot series, in percent: a pixel ROC has a point per distinct score, far more than a
// plot shows, and a plot zoomed to low FPRs must still reach its right edge. Of each of `bins`
// FPR bins up to `max_fpr` the series keeps the last point (the highest TPR there, so that steps
// keep their height), plus the first point and one interpolated at `max_fpr`.
#pragma once

#include <string>

#include "eval/html_report.h"
#include "eval/roc.h"

namespace novelty::eval {

struct RocPlotOptions {
  /// Largest FPR shown (a fraction): 1 for the whole curve, e.g. 0.05 to zoom on low FPRs.
  double max_fpr = 1.0;
  /// FPR bins of width max_fpr / bins, one point each (a point at max_fpr exactly opens one
  /// more); an ROC over a few hundred decisions keeps nearly all its points.
  int bins = 400;
};

/// Throws std::invalid_argument if options.max_fpr is not in (0, 1] or options.bins < 1.
PlotSeries RocPlotSeries(const Roc& roc, const std::string& name, const std::string& color,
                         const RocPlotOptions& options = {});

}  // namespace novelty::eval
