#include "eval/roc_plot.h"

#include <cmath>
#include <stdexcept>

namespace novelty::eval {

PlotSeries RocPlotSeries(const Roc& roc, const std::string& name, const std::string& color,
                         const RocPlotOptions& options) {
  if (!(options.max_fpr > 0.0 && options.max_fpr <= 1.0))
    throw std::invalid_argument("RocPlotSeries: max_fpr must be in (0, 1], got " +
                                std::to_string(options.max_fpr));
  if (options.bins < 1)
    throw std::invalid_argument("RocPlotSeries: bins must be ≥ 1, got " +
                                std::to_string(options.bins));
  PlotSeries s{name, color, {}, 0.0};
  const std::vector<RocPoint>& p = roc.points;
  const double max_fpr = options.max_fpr, bin = max_fpr / options.bins;
  std::size_t i = 0;
  for (; i < p.size() && p[i].fpr <= max_fpr; ++i) {
    const bool last_of_bin = i + 1 == p.size() || p[i + 1].fpr > max_fpr ||
                             std::floor(p[i + 1].fpr / bin) != std::floor(p[i].fpr / bin);
    if (i == 0 || last_of_bin) s.points.emplace_back(100 * p[i].fpr, 100 * p[i].tpr);
  }
  if (i > 0 && i < p.size() && p[i - 1].fpr < max_fpr) {
    const RocPoint &a = p[i - 1], &b = p[i];
    const double t = (max_fpr - a.fpr) / (b.fpr - a.fpr);
    s.points.emplace_back(100 * max_fpr, 100 * (a.tpr + t * (b.tpr - a.tpr)));
  }
  return s;
}

}  // namespace novelty::eval
