#include "maps/stats/gamma_ml_fit.h"

#include <cmath>
#include <stdexcept>

#include "maps/stats/special_functions.h"

namespace novelty::stats {

namespace {

struct SampleMoments {
  double mean = 0.0;
  double mean_log = 0.0;
  std::size_t used = 0;
  std::size_t skipped = 0;
};

SampleMoments Moments(const std::vector<double>& samples, const GammaFitOptions& o) {
  SampleMoments m;
  double sum = 0.0, sum_log = 0.0;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const double y = samples[i];
    if (!(std::isfinite(y) && y > 0.0)) {
      if (o.non_positive == GammaFitOptions::NonPositive::kError) {
        throw std::invalid_argument("FitGammaML: sample " + std::to_string(i) + " is " +
                                    std::to_string(y) + "; gamma samples must be > 0 and finite");
      }
      ++m.skipped;
      continue;
    }
    sum += y;
    sum_log += std::log(y);
    ++m.used;
  }
  if (m.used == 0) {
    throw std::invalid_argument("FitGammaML: no positive finite sample among " +
                                std::to_string(samples.size()) + " (" + std::to_string(m.skipped) +
                                " skipped)");
  }
  m.mean = sum / static_cast<double>(m.used);
  m.mean_log = sum_log / static_cast<double>(m.used);
  return m;
}

}  // namespace

GammaFit FitGammaML(const std::vector<double>& samples, const GammaFitOptions& options) {
  const SampleMoments m = Moments(samples, options);
  GammaFit fit;
  fit.used = m.used;
  fit.skipped = m.skipped;
  const double spread = std::log(m.mean) - m.mean_log;  // right side of eq. 2.14, >= 0 by Jensen
  if (spread < options.min_spread) {
    fit.status = GammaFit::Status::kConstant;
    fit.alpha = options.max_alpha;
    fit.beta = fit.alpha / m.mean;
    return fit;
  }
  double alpha = 1.0 / (2.0 * spread);  // eq. 2.17
  fit.status = GammaFit::Status::kMaxIterations;
  for (int it = 1; it <= options.max_iterations; ++it) {
    // eq. 2.16: Newton step on g(α) = ln α - ψ(α) - spread, g'(α) = 1/α - ψ'(α) < 0.
    const double g = std::log(alpha) - Digamma(alpha) - spread;
    const double dg = 1.0 / alpha - Trigamma(alpha);
    double next = alpha - g / dg;
    // g is convex and decreasing, so Newton from the left never overshoots to ≤ 0; guard anyway.
    if (!(next > 0.0)) next = 0.5 * alpha;
    fit.iterations = it;
    const bool done = std::abs(next - alpha) <= options.tolerance * alpha;
    alpha = next;
    if (done) {
      fit.status = GammaFit::Status::kConverged;
      break;
    }
  }
  fit.alpha = alpha;
  fit.beta = alpha / m.mean;  // eq. 2.12
  return fit;
}

std::string ToString(GammaFit::Status status) {
  switch (status) {
    case GammaFit::Status::kConverged:
      return "converged";
    case GammaFit::Status::kConstant:
      return "constant samples";
    case GammaFit::Status::kMaxIterations:
      return "max iterations reached";
  }
  return "unknown";
}

}  // namespace novelty::stats
