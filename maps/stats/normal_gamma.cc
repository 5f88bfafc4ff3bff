#include "maps/stats/normal_gamma.h"

#include <cmath>
#include <stdexcept>

namespace novelty::stats {

namespace {
void RequirePositive(double v, const std::string& name, const std::string& what) {
  if (!(std::isfinite(v) && v > 0.0)) {
    throw std::invalid_argument(what + ": " + name + " must be a positive finite number, got " +
                                std::to_string(v));
  }
}
}  // namespace

void CheckNormalGamma(const NormalGamma& p, const std::string& what) {
  RequirePositive(p.alpha, "alpha", what);
  RequirePositive(p.beta, "beta", what);
  RequirePositive(p.sigma, "sigma", what);
  if (!std::isfinite(p.tau)) throw std::invalid_argument(what + ": tau must be finite");
}

NormalGamma UpdateOneSample(const NormalGamma& prior, double x) {
  const double d = x - prior.tau;
  return {prior.alpha + 0.5,                                    // eq. 4.4
          prior.beta + 0.5 * d * d / (prior.sigma + 1.0),       // eq. 4.5
          (prior.sigma * x + prior.tau) / (prior.sigma + 1.0),  // eq. 4.6
          prior.sigma / (prior.sigma + 1.0)};                   // eq. 4.7
}

NormalGamma UpdateSamples(const NormalGamma& prior, const std::vector<double>& z) {
  if (z.empty()) throw std::invalid_argument("UpdateSamples: no samples");
  const double n = static_cast<double>(z.size());
  double sum = 0.0;
  for (double v : z) sum += v;
  const double mean = sum / n;
  double scatter = 0.0;
  for (double v : z) scatter += (v - mean) * (v - mean);
  const double d = mean - prior.tau;
  const double denom = prior.sigma * n + 1.0;
  return {prior.alpha + 0.5 * n,                                   // eq. 2.22
          prior.beta + 0.5 * scatter + 0.5 * d * d / (denom / n),  // eq. 2.23
          (prior.sigma * sum + prior.tau) / denom,                 // eq. 2.24
          prior.sigma / denom};                                    // eq. 2.25
}

void ForgettingUpdateOptions::Check() const {
  if (!(forgetting_factor > 0.0 && forgetting_factor < 1.0)) {
    throw std::invalid_argument(
        "ForgettingUpdateOptions: forgetting_factor must be in (0, 1), got " +
        std::to_string(forgetting_factor));
  }
  if (!(std::isfinite(xi) && xi >= 0.0)) {
    throw std::invalid_argument("ForgettingUpdateOptions: xi must be finite and >= 0, got " +
                                std::to_string(xi));
  }
  if (!(std::isfinite(min_variance) && min_variance >= 0.0)) {
    throw std::invalid_argument(
        "ForgettingUpdateOptions: min_variance must be finite and >= 0, got " +
        std::to_string(min_variance));
  }
  if (!(sigma_min > 0.0 && sigma_max >= sigma_min && std::isfinite(sigma_max))) {
    throw std::invalid_argument(
        "ForgettingUpdateOptions: need 0 < sigma_min <= sigma_max < inf, got sigma_min=" +
        std::to_string(sigma_min) + " sigma_max=" + std::to_string(sigma_max));
  }
}

double AlphaAfterUpdates(double alpha0, int n, double forgetting_factor) {
  const double fn = std::pow(forgetting_factor, n);
  return fn * alpha0 + 0.5 * (1.0 - fn) / (1.0 - forgetting_factor);
}

}  // namespace novelty::stats
