// Maximum-likelihood fit of a gamma distribution p(y) = β^α/Γ(α) y^(α-1) e^(-βy) to positive
// samples, by Newton-Raphson on the profile likelihood (eq. 2.12-2.17, Choi & Wette 1969).
// Used for the illumination statistics of chapter 6 (luminance and saturation ratios).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace novelty::stats {

struct GammaFitOptions {
  /// How samples that are not > 0 (a gamma variate is positive) are handled.
  enum class NonPositive {
    kSkip,   ///< left out and counted in GammaFit::skipped (default: dark pixels carry no ratio)
    kError,  ///< std::invalid_argument naming the first such sample's index
  };
  NonPositive non_positive = NonPositive::kSkip;
  /// Newton-Raphson stops when the relative change of α is below this.
  double tolerance = 1e-12;
  int max_iterations = 100;
  /// Samples whose spread s = ln(mean) - mean(ln y) (eq. 2.14's right side, ≥ 0) is below this
  /// are treated as constant: α would be infinite. The fit then reports kConstant with α =
  /// max_alpha and β = α / mean (a gamma distribution as narrow as representable around the mean).
  double min_spread = 1e-12;
  double max_alpha = 1e8;
};

struct GammaFit {
  enum class Status { kConverged, kConstant, kMaxIterations };
  double alpha = 0.0;  ///< shape α
  double beta = 0.0;   ///< rate β (eq. 2.12: β = α / mean)
  Status status = Status::kConverged;
  int iterations = 0;
  std::size_t used = 0;     ///< samples that entered the fit
  std::size_t skipped = 0;  ///< samples ≤ 0 or not finite that were left out
};

/// Fits α, β. Throws std::invalid_argument when no usable sample remains (the message says how
/// many were given and skipped) or, with NonPositive::kError, on the first bad sample.
GammaFit FitGammaML(const std::vector<double>& samples, const GammaFitOptions& options = {});

std::string ToString(GammaFit::Status status);

}  // namespace novelty::stats
